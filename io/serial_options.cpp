#include "io/serial_options.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/port_discovery.hpp"
#include "io/serial_port.hpp"
#include "io/serial_sink.hpp"
#include "foundation/error.hpp"

namespace lattice::io {

void SerialOptions::validate() const {
  if (port.empty()) throw Error(ErrorKind::Usage, "--port: empty; give a device such as /dev/ttyUSB0, or auto");
  // 50 baud is the slowest Linux rate, 4 Mbaud the fastest common UARTs reach.
  if (baud < 50 || baud > 4000000)
    throw Error(ErrorKind::Usage,
                fmt::format("--baud {}: out of range; use 50..4000000, usually 9600, 19200 or 38400 to match "
                            "the terminal's setup",
                            baud));
  if (dataBits != 7 && dataBits != 8)
    throw Error(ErrorKind::Usage, fmt::format("--data-bits {}: use 7 or 8", dataBits));
  if (stopBits != 1 && stopBits != 2)
    throw Error(ErrorKind::Usage, fmt::format("--stop-bits {}: use 1 or 2", stopBits));
  if (!(stallTimeoutSeconds > 0.0) || !std::isfinite(stallTimeoutSeconds))
    throw Error(ErrorKind::Usage,
                fmt::format("--stall-timeout {}: use a positive number of seconds", stallTimeoutSeconds));
}

Parity parseParity(std::string_view text) {
  if (const auto parity = valueNamed(kParityNames, text)) return *parity;
  throw Error(ErrorKind::Usage, fmt::format("--parity {}: use {}", text, choicesOf(kParityNames)));
}

FlowControl parseFlowControl(std::string_view text) {
  if (const auto flow = valueNamed(kFlowControlNames, text)) return *flow;
  throw Error(ErrorKind::Usage, fmt::format("--flow {}: use {}", text, choicesOf(kFlowControlNames)));
}

std::string_view toString(Parity parity) { return nameOfValue(kParityNames, parity, "none"); }

std::string_view toString(FlowControl flow) { return nameOfValue(kFlowControlNames, flow, "none"); }

std::string serialFlags(const SerialOptions& options) {
  std::string flags = fmt::format("--port {} --baud {} --flow {}", options.port, options.baud, toString(options.flow));
  if (options.dataBits != 8 || options.parity != Parity::None || options.stopBits != 1)
    flags += fmt::format(" --data-bits {} --parity {} --stop-bits {}", options.dataBits, toString(options.parity),
                         options.stopBits);
  flags += fmt::format(" --stall-timeout {:g}", options.stallTimeoutSeconds);
  if (options.pace) flags += " --pace";
  return flags;
}

std::unique_ptr<SerialSink> openSerialSink(const SerialOptions& options, const std::filesystem::path& sysfsRoot,
                                           const std::filesystem::path& devRoot) {
  options.validate();
  SerialOptions resolved = options;
  if (resolved.port == "auto") resolved.port = chooseAutoPort(listSerialPorts(sysfsRoot, devRoot));
  return std::make_unique<SerialSink>(SerialPort(resolved.port), resolved);
}

}  // namespace lattice::io
