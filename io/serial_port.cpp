#include "io/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <utility>

#include "io/serial_termios2.hpp"
#include "foundation/error.hpp"

namespace lattice::io {
namespace {

struct BaudConstant {
  int baud;
  speed_t constant;
};

constexpr std::array kStandardBauds{
    BaudConstant{50, B50},           BaudConstant{75, B75},           BaudConstant{110, B110},
    BaudConstant{134, B134},         BaudConstant{150, B150},         BaudConstant{200, B200},
    BaudConstant{300, B300},         BaudConstant{600, B600},         BaudConstant{1200, B1200},
    BaudConstant{1800, B1800},       BaudConstant{2400, B2400},       BaudConstant{4800, B4800},
    BaudConstant{9600, B9600},       BaudConstant{19200, B19200},     BaudConstant{38400, B38400},
    BaudConstant{57600, B57600},     BaudConstant{115200, B115200},   BaudConstant{230400, B230400},
    BaudConstant{460800, B460800},   BaudConstant{500000, B500000},   BaudConstant{576000, B576000},
    BaudConstant{921600, B921600},   BaudConstant{1000000, B1000000}, BaudConstant{1152000, B1152000},
    BaudConstant{1500000, B1500000}, BaudConstant{2000000, B2000000}, BaudConstant{2500000, B2500000},
    BaudConstant{3000000, B3000000}, BaudConstant{3500000, B3500000}, BaudConstant{4000000, B4000000},
};

[[noreturn]] void throwOpenError(const std::string& path, int err) {
  switch (err) {
    case ENOENT:
    case ENODEV:
    case ENXIO:
      throw Error(ErrorKind::Serial,
                  fmt::format("{}: no such serial port ({}); `lattice ports` lists the ports present, and "
                              "`--port auto` picks a single USB-serial adapter",
                              path, std::strerror(err)));
    case EACCES:
    case EPERM:
      throw Error(ErrorKind::Serial,
                  fmt::format("{}: permission denied; add yourself to the group that owns the port "
                              "(usually dialout: `sudo usermod -aG dialout $USER`, then log in again)",
                              path));
    case EBUSY:
    case EWOULDBLOCK:
      throw Error(ErrorKind::Serial,
                  fmt::format("{}: the port is busy: another program has it open (a terminal program such "
                              "as screen or minicom, ModemManager, or another lattice); close it and retry",
                              path));
    case ENOTTY:
      throw Error(ErrorKind::Serial,
                  fmt::format("{}: not a serial port (it has no terminal settings); give a tty device such "
                              "as /dev/ttyUSB0, see `lattice ports`",
                              path));
    default:
      throw Error(ErrorKind::Serial, fmt::format("{}: cannot open the serial port: {}", path, std::strerror(err)));
  }
}

}  // namespace

bool isStandardBaud(int baud) {
  for (const auto& entry : kStandardBauds)
    if (entry.baud == baud) return true;
  return false;
}

SerialPort::SerialPort(std::string path) : path_(std::move(path)) {
  // O_NOCTTY: a terminal line must never become our controlling tty (a hang-up
  // would then signal us). O_NONBLOCK: also keeps open() from waiting for DCD.
  fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throwOpenError(path_, errno);
  termios probe{};
  if (::tcgetattr(fd_, &probe) != 0) {
    int err = errno;
    close();
    throwOpenError(path_, err == EINVAL ? ENOTTY : err);
  }
  // flock catches a second lattice (and ourselves) even as root, which
  // TIOCEXCL does not stop; TIOCEXCL keeps out programs that do not flock.
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    int err = errno;
    close();
    throwOpenError(path_, err == EWOULDBLOCK ? EBUSY : err);
  }
  if (::ioctl(fd_, TIOCEXCL) != 0) {
    int err = errno;
    close();
    throwOpenError(path_, err);
  }
  // Unix98 pty slaves have majors 136..143 (Documentation/admin-guide/devices.txt).
  struct stat info {};
  if (::fstat(fd_, &info) == 0 && S_ISCHR(info.st_mode)) {
    unsigned major = ::major(info.st_rdev);
    isPty_ = major >= 136 && major <= 143;
  }
}

SerialPort::~SerialPort() { close(); }

SerialPort::SerialPort(SerialPort&& other) noexcept
    : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)), isPty_(other.isPty_) {}

SerialPort& SerialPort::operator=(SerialPort&& other) noexcept {
  if (this != &other) {
    close();
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
    isPty_ = other.isPty_;
  }
  return *this;
}

void SerialPort::configure(const SerialOptions& options) {
  options.validate();
  termios settings{};
  if (::tcgetattr(fd_, &settings) != 0)
    throw Error(ErrorKind::Serial, fmt::format("{}: cannot read the line settings: {}", path_, std::strerror(errno)));
  // cfmakeraw: no echo, no line editing, no CR/LF translation, no signals -
  // every byte of a command stream goes out as it is. It also clears IXON and
  // IXOFF, so flow control is set after it.
  ::cfmakeraw(&settings);
  settings.c_cflag |= CLOCAL | CREAD;  // ignore modem lines; a null-modem cable has no DCD
  settings.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  settings.c_cflag |= options.dataBits == 7 ? CS7 : CS8;
  if (options.parity != Parity::None) settings.c_cflag |= PARENB;
  if (options.parity == Parity::Odd) settings.c_cflag |= PARODD;
  if (options.stopBits == 2) settings.c_cflag |= CSTOPB;
  settings.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  switch (options.flow) {
    case FlowControl::XonXoff:
      // IXON: the line discipline stops our output on DC3 and restarts it on
      // DC1 and swallows both. IXOFF: we send DC3/DC1 if our input fills up.
      settings.c_iflag |= IXON | IXOFF;
      break;
    case FlowControl::RtsCts:
      settings.c_cflag |= CRTSCTS;
      break;
    case FlowControl::None:
      break;
  }
  settings.c_cc[VMIN] = 0;
  settings.c_cc[VTIME] = 0;
  const bool standard = isStandardBaud(options.baud);
  if (standard) {
    for (const auto& entry : kStandardBauds)
      if (entry.baud == options.baud) ::cfsetspeed(&settings, entry.constant);
  }
  // Output stopped by an XOFF that arrived before we opened the port (or
  // while a previous send was stalled) would stay stopped: the terminal
  // sent its XON to nobody. Turning IXON off restarts output (n_tty), so
  // apply the settings once without it; any XOFF from now on is honoured.
  termios released = settings;
  released.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF);
  if (::tcsetattr(fd_, TCSANOW, &released) != 0 || ::tcsetattr(fd_, TCSANOW, &settings) != 0)
    throw Error(ErrorKind::Serial,
                fmt::format("{}: the driver refused the line settings ({}): {}", path_, serialFlags(options),
                            std::strerror(errno)));
  if (!standard) {
    if (int err = detail::setBaudTermios2(fd_, options.baud); err != 0)
      throw Error(ErrorKind::Serial,
                  fmt::format("{}: the driver refused the non-standard baud rate {} ({}); use a standard rate "
                              "such as 9600, 19200 or 38400 and set the terminal to match",
                              path_, options.baud, std::strerror(err)));
  }

  // tcsetattr succeeds if the driver applied any part of the request, so
  // read the settings back and name whatever it did not take.
  termios actual{};
  if (::tcgetattr(fd_, &actual) != 0)
    throw Error(ErrorKind::Serial, fmt::format("{}: cannot read the line settings: {}", path_, std::strerror(errno)));
  if ((actual.c_cflag & CSIZE) != (settings.c_cflag & CSIZE) ||
      (actual.c_cflag & (PARENB | PARODD | CSTOPB)) != (settings.c_cflag & (PARENB | PARODD | CSTOPB)))
    throw Error(ErrorKind::Serial,
                fmt::format("{}: the driver does not support {} data bits, parity {}, {} stop bits{}", path_,
                            options.dataBits, toString(options.parity), options.stopBits,
                            isPty_ ? " (this is a pty, which is always 8 data bits without parity: use "
                                     "--data-bits 8 --parity none)"
                                   : "; check the adapter's documentation or use 8 data bits, no parity"));
  if ((actual.c_cflag & CRTSCTS) != (settings.c_cflag & CRTSCTS))
    throw Error(ErrorKind::Serial,
                fmt::format("{}: the driver does not support RTS/CTS flow control; use --flow xonxoff", path_));
  long speed = detail::readBaudTermios2(fd_);
  // A UART divides its clock by an integer, so the driver may round: accept
  // within 2 %, about what an asynchronous receiver tolerates.
  if (speed > 0 && std::abs(static_cast<double>(speed - options.baud)) > 0.02 * options.baud)
    throw Error(ErrorKind::Serial,
                fmt::format("{}: the driver set {} baud when asked for {}; use a standard rate such as 9600, "
                            "19200 or 38400",
                            path_, speed, options.baud));
}

SerialPort::WriteResult SerialPort::writeSome(std::span<const std::uint8_t> bytes) {
  for (;;) {
    ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n >= 0) return {static_cast<std::size_t>(n), n > 0 ? Status::Progress : Status::WouldBlock};
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return {0, Status::WouldBlock};
    // EIO: the other end hung up (pty master closed, USB adapter unplugged);
    // anything else on a port we configured fine is as final.
    return {0, Status::HangUp};
  }
}

SerialPort::Wait SerialPort::waitWritable(int timeoutMs) {
  pollfd entry{fd_, POLLOUT, 0};
  for (;;) {
    int r = ::poll(&entry, 1, timeoutMs);
    if (r < 0 && errno == EINTR) continue;  // a signal is no reason to give up; the caller re-checks time
    if (r < 0) return Wait::HangUp;
    if (r == 0) return Wait::Timeout;
    if (entry.revents & (POLLHUP | POLLERR | POLLNVAL)) return Wait::HangUp;
    return Wait::Writable;
  }
}

std::size_t SerialPort::outputQueued() const {
  int queued = 0;
  if (::ioctl(fd_, TIOCOUTQ, &queued) != 0 || queued < 0) return 0;
  return static_cast<std::size_t>(queued);
}

void SerialPort::discardOutput() { ::tcflush(fd_, TCOFLUSH); }
void SerialPort::discardInput() { ::tcflush(fd_, TCIFLUSH); }

void SerialPort::drainQueued() {
  while (::tcdrain(fd_) != 0 && errno == EINTR) {
  }
}

void SerialPort::close() {
  if (fd_ < 0) return;
  ::ioctl(fd_, TIOCNXCL);
  ::close(fd_);  // also releases the flock
  fd_ = -1;
}

}  // namespace lattice::io
