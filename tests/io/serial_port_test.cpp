// Opening and configuring a port: exclusivity, bad paths, bad settings, and
// what the driver (here a pty's) really accepted.
#include <catch2/catch.hpp>

#include <termios.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "io/pty.hpp"
#include "io/serial_port.hpp"
#include "io/serial_termios2.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;

namespace {

std::string messageOf(const std::function<void()>& action, ErrorKind expected) {
  try {
    action();
  } catch (const Error& e) {
    CHECK(e.kind() == expected);
    return e.what();
  }
  FAIL("expected a lattice::Error");
  return {};
}

}  // namespace

TEST_CASE("A port is exclusive: a second open is refused as busy", "[serial]") {
  PtyPair pty;
  SerialPort first(pty.slavePath());
  auto message = messageOf([&] { SerialPort second(pty.slavePath()); }, ErrorKind::Serial);
  CHECK(message.find(pty.slavePath()) != std::string::npos);
  CHECK(message.find("busy") != std::string::npos);
  first.close();
  SerialPort again(pty.slavePath());  // free once the first is closed
  CHECK(again.isOpen());
}

TEST_CASE("Opening a path that is not a serial port says what is wrong", "[serial]") {
  auto missing = messageOf([] { SerialPort port("/dev/lattice-no-such-tty"); }, ErrorKind::Serial);
  CHECK(missing.find("/dev/lattice-no-such-tty") != std::string::npos);
  CHECK(missing.find("no such serial port") != std::string::npos);
  CHECK(missing.find("lattice ports") != std::string::npos);

  auto notTty = messageOf([] { SerialPort port("/dev/null"); }, ErrorKind::Serial);
  CHECK(notTty.find("not a serial port") != std::string::npos);

  auto file = std::filesystem::temp_directory_path() / "lattice-serial-port-test.txt";
  std::ofstream(file) << "plain file";
  auto plain = messageOf([&] { SerialPort port(file.string()); }, ErrorKind::Serial);
  CHECK(plain.find("not a serial port") != std::string::npos);
  std::filesystem::remove(file);
}

TEST_CASE("configure applies raw mode, line format and flow control", "[serial]") {
  PtyPair pty;
  SerialPort port(pty.slavePath());
  CHECK(port.isPty());
  SerialOptions options;
  options.port = pty.slavePath();
  options.baud = 19200;
  options.stopBits = 2;
  options.flow = FlowControl::XonXoff;
  port.configure(options);

  termios actual{};
  REQUIRE(::tcgetattr(port.fd(), &actual) == 0);
  CHECK((actual.c_cflag & CSIZE) == CS8);
  CHECK((actual.c_cflag & PARENB) == 0);
  CHECK((actual.c_cflag & CSTOPB) != 0);
  // cfmakeraw clears IXON/IXOFF; they must have been set again after it.
  CHECK((actual.c_iflag & IXON) != 0);
  CHECK((actual.c_iflag & IXOFF) != 0);
  CHECK((actual.c_lflag & (ICANON | ECHO | ISIG)) == 0);
  CHECK((actual.c_oflag & OPOST) == 0);
  CHECK(::cfgetospeed(&actual) == B19200);

  options.flow = FlowControl::RtsCts;
  options.stopBits = 1;
  port.configure(options);
  REQUIRE(::tcgetattr(port.fd(), &actual) == 0);
  CHECK((actual.c_iflag & IXON) == 0);
  CHECK((actual.c_cflag & CRTSCTS) != 0);
  CHECK((actual.c_cflag & CSTOPB) == 0);
}

TEST_CASE("A line format the driver does not take is refused, not silently changed", "[serial]") {
  // Linux's pty driver forces CS8 and clears PARENB whatever is asked; the
  // read-back must notice, as it would for a USB adapter without 7-bit mode.
  PtyPair pty;
  SerialPort port(pty.slavePath());
  SerialOptions options;
  options.port = pty.slavePath();
  options.dataBits = 7;
  options.parity = Parity::Even;
  auto message = messageOf([&] { port.configure(options); }, ErrorKind::Serial);
  CHECK(message.find("does not support 7 data bits, parity even") != std::string::npos);
  CHECK(message.find("pty") != std::string::npos);
}

TEST_CASE("A non-standard baud rate goes through termios2", "[serial]") {
  CHECK(isStandardBaud(38400));
  CHECK_FALSE(isStandardBaud(31250));
  PtyPair pty;
  SerialPort port(pty.slavePath());
  SerialOptions options;
  options.port = pty.slavePath();
  options.baud = 31250;  // MIDI's rate: no B constant
  port.configure(options);
  CHECK(detail::readBaudTermios2(port.fd()) == 31250);
}

TEST_CASE("Impossible line settings are usage errors naming the setting and its value", "[serial]") {
  PtyPair pty;
  SerialPort port(pty.slavePath());
  SerialOptions options;
  options.port = pty.slavePath();
  options.baud = 10;
  CHECK(messageOf([&] { port.configure(options); }, ErrorKind::Usage).find("baud=10") != std::string::npos);
  options.baud = 9600;
  options.dataBits = 6;
  CHECK(messageOf([&] { port.configure(options); }, ErrorKind::Usage).find("data-bits=6") != std::string::npos);
  options.dataBits = 8;
  options.stopBits = 3;
  CHECK(messageOf([&] { port.configure(options); }, ErrorKind::Usage).find("stop-bits=3") != std::string::npos);
  options.stopBits = 1;
  options.stallTimeoutSeconds = 0;
  CHECK(messageOf([&] { port.configure(options); }, ErrorKind::Usage).find("stall-timeout=0") != std::string::npos);
}
