#pragma once
// The terminal on a serial line: a USB adapter, the firmware's UART, a SimH
// console on a pty. The port is opened and set up by the project's own
// serial code (io/serial_port.hpp: exclusive, raw, the line's baud, format
// and flow control), so XON/XOFF toward the host is the kernel's. The line
// ends when it hangs up: poll's POLLHUP or POLLERR, or a read that fails with
// EIO (a pty whose far side closed, a USB adapter unplugged). A read of
// nothing is not an end: the line is raw with VMIN 0, where an empty read
// only means no byte is waiting.
#include "app/term/term_source.hpp"
#include "io/serial_port.hpp"

namespace lattice::app {

class PortSource final : public TermSource {
 public:
  explicit PortSource(const io::SerialOptions& line);
  int fd() const override { return port_.fd(); }
  bool read(std::vector<std::uint8_t>& out) override;
  void write(std::span<const std::uint8_t> bytes) override;
  std::string endReason() const override;

 private:
  io::SerialPort port_;
};

}  // namespace lattice::app
