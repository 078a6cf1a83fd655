#pragma once
// How to reach a terminal over a serial line: the port and its line settings.
// `lattice send` and `lattice render --port` take the same flags
// (app/cli/serial_args.hpp) and open the line with openSerialSink().
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "foundation/line_timing.hpp"
#include "foundation/name_table.hpp"

namespace lattice::io {

enum class Parity { None, Even, Odd };
enum class FlowControl { None, XonXoff, RtsCts };

// Their flag spellings (`--parity`, `--flow`), in the order help lists them.
inline constexpr std::array<EnumName<Parity>, 3> kParityNames = {{
    {Parity::None, "none"},
    {Parity::Even, "even"},
    {Parity::Odd, "odd"},
}};
inline constexpr std::array<EnumName<FlowControl>, 3> kFlowControlNames = {{
    {FlowControl::XonXoff, "xonxoff"},
    {FlowControl::RtsCts, "rtscts"},
    {FlowControl::None, "none"},
}};

struct SerialOptions {
  std::string port = "auto";  // a device path, or "auto": the only USB-serial adapter
  int baud = 9600;
  int dataBits = 8;           // 7 or 8
  Parity parity = Parity::None;
  int stopBits = 1;           // 1 or 2
  FlowControl flow = FlowControl::XonXoff;  // Tektronix terminals "flag" with DC1/DC3
  double stallTimeoutSeconds = 30.0;        // no progress for this long -> ErrorKind::Stalled
  bool pace = false;          // limit our own rate to the baud rate (ptys, network bridges)

  LineFormat lineFormat() const { return {baud, dataBits, parity != Parity::None, stopBits}; }
  // Throws Error(Usage) naming the bad setting and the accepted values.
  void validate() const;
};

// The names of kParityNames and kFlowControlNames, for messages (the flags
// read them through io/serial_settings.hpp).
std::string_view toString(Parity parity);
std::string_view toString(FlowControl flow);

// The flags that reproduce these options ("--port /dev/ttyUSB0 --baud 9600 ..."),
// so an error can print the exact command to resume with.
std::string serialFlags(const SerialOptions& options);

class SerialSink;
// Resolves "auto" through port discovery under sysfsRoot, opens and configures
// the port. Errors: Usage (bad settings), Serial (no such port, busy, refused).
std::unique_ptr<SerialSink> openSerialSink(const SerialOptions& options,
                                           const std::filesystem::path& sysfsRoot = "/sys",
                                           const std::filesystem::path& devRoot = "/dev");

}  // namespace lattice::io
