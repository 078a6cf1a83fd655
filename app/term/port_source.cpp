#include "app/term/port_source.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>

#include "app/term/term_write.hpp"
#include "io/port_discovery.hpp"

namespace lattice::app {

namespace {

std::string resolvedPort(const io::SerialOptions& line) {
  line.validate();
  return line.port == "auto" ? io::chooseAutoPort(io::listSerialPorts()) : line.port;
}

}  // namespace

PortSource::PortSource(const io::SerialOptions& line) : port_(resolvedPort(line)) {
  port_.configure(line);
}

bool PortSource::read(std::vector<std::uint8_t>& out) {
  std::uint8_t buffer[65536];
  for (;;) {
    const ssize_t n = ::read(port_.fd(), buffer, sizeof buffer);
    if (n > 0) {
      out.insert(out.end(), buffer, buffer + n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 || (n < 0 && errno == EAGAIN)) {
      // Nothing to read (the line is raw with VMIN 0, so an empty read is not
      // the end of a file): a line whose far side has gone says so through poll.
      pollfd p{port_.fd(), 0, 0};
      return !(::poll(&p, 1, 0) == 1 && (p.revents & (POLLHUP | POLLERR)));
    }
    return false;  // EIO: the line hung up (a pty whose far side closed, an adapter unplugged)
  }
}

void PortSource::write(std::span<const std::uint8_t> bytes) { writeToPeer(port_.fd(), bytes); }

std::string PortSource::endReason() const { return fmt::format("{} hung up", port_.path()); }

}  // namespace lattice::app
