// Flag spellings and the flags an error prints for resuming.
#include <catch2/catch.hpp>

#include "io/serial_options.hpp"
#include "io/stream_sender.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;

TEST_CASE("Parity and flow control parse from their flag spellings", "[serial]") {
  CHECK(parseParity("even") == Parity::Even);
  CHECK(parseParity("odd") == Parity::Odd);
  CHECK(parseParity("none") == Parity::None);
  CHECK(parseFlowControl("rtscts") == FlowControl::RtsCts);
  CHECK(parseFlowControl("xonxoff") == FlowControl::XonXoff);
  CHECK(parseFlowControl("none") == FlowControl::None);
  CHECK_THROWS_AS(parseParity("mark"), Error);
  CHECK_THROWS_AS(parseFlowControl("dtrdsr"), Error);
  for (auto p : {Parity::None, Parity::Even, Parity::Odd}) CHECK(parseParity(toString(p)) == p);
  for (auto f : {FlowControl::None, FlowControl::XonXoff, FlowControl::RtsCts}) CHECK(parseFlowControl(toString(f)) == f);
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
        "--stop-bits 1 --stall-timeout 12.5 --pace --resume 7");
  CHECK(resumeCommand("it's.tek", options, 0).rfind("lattice send 'it'\\''s.tek' ", 0) == 0);
}
