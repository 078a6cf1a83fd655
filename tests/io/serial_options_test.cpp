// The line's spellings (its settings table) and the flags an error prints for resuming.
#include <catch2/catch.hpp>

#include "io/serial_options.hpp"
#include "io/serial_settings.hpp"
#include "io/stream_sender.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;

TEST_CASE("Parity and flow control are read from their spellings in the line's settings table", "[serial]") {
  SerialOptions options;
  applySetting(serialSettings(), options, "parity=even");
  CHECK(options.parity == Parity::Even);
  applySetting(serialSettings(), options, "flow=rtscts");
  CHECK(options.flow == FlowControl::RtsCts);
  CHECK_THROWS_AS(applySetting(serialSettings(), options, "parity=mark"), Error);
  CHECK_THROWS_AS(applySetting(serialSettings(), options, "flow=dtrdsr"), Error);
  CHECK_THROWS_AS(applySetting(serialSettings(), options, "baud=nan"), Error);
  CHECK_THROWS_AS(applySetting(serialSettings(), options, "stall-timeout=inf"), Error);
  CHECK(options.parity == Parity::Even);  // a refused value leaves the line as it was
  for (auto p : {Parity::None, Parity::Even, Parity::Odd}) {
    applySetting(serialSettings(), options, "parity=" + std::string(toString(p)));
    CHECK(options.parity == p);
  }
  for (auto f : {FlowControl::None, FlowControl::XonXoff, FlowControl::RtsCts}) {
    applySetting(serialSettings(), options, "flow=" + std::string(toString(f)));
    CHECK(options.flow == f);
  }
}

TEST_CASE("The line format counts parity and stop bits", "[serial]") {
  SerialOptions options;
  CHECK(options.lineFormat().bitsPerCharacter() == 10);
  options.dataBits = 7;
  options.parity = Parity::Even;
  options.stopBits = 2;
  CHECK(options.lineFormat().bitsPerCharacter() == 11);
}

TEST_CASE("The resume command reproduces every setting", "[serial]") {
  SerialOptions options;
  options.port = "/dev/ttyUSB0";
  options.baud = 19200;
  options.flow = FlowControl::RtsCts;
  options.stallTimeoutSeconds = 12.5;
  CHECK(resumeCommand("out/teapot.tek", options, 4242) ==
        "lattice send out/teapot.tek --port /dev/ttyUSB0 --baud 19200 --flow rtscts --stall-timeout 12.5 "
        "--resume 4242");
  options.dataBits = 7;
  options.parity = Parity::Odd;
  options.pace = true;
  CHECK(resumeCommand("my picture.tek", options, 7) ==
        "lattice send 'my picture.tek' --port /dev/ttyUSB0 --baud 19200 --flow rtscts --data-bits 7 --parity odd "
        "--stall-timeout 12.5 --pace --resume 7");
  options = SerialOptions{};  // the defaults: only the port and the rate
  options.port = "/dev/ttyS0";
  CHECK(resumeCommand("a.tek", options, 1) == "lattice send a.tek --port /dev/ttyS0 --baud 9600 --resume 1");
  CHECK(resumeCommand("it's.tek", options, 0).rfind("lattice send 'it'\\''s.tek' ", 0) == 0);
}
