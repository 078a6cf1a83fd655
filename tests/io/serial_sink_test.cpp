// SerialSink against a real peer: the master side of a pty reads what the
// sink writes into the slave side, exactly as a terminal on a cable would.
#include <catch2/catch.hpp>

#include <chrono>
#include <random>

#include "io/pty.hpp"
#include "io/serial_port.hpp"
#include "io/serial_sink.hpp"
#include "pty_peer.hpp"

using namespace lattice;
using namespace lattice::io;
using lattice::testing::PtyPeer;

namespace {

SerialOptions ptyOptions(const PtyPair& pty, FlowControl flow) {
  SerialOptions options;
  options.port = pty.slavePath();
  options.baud = 38400;
  options.flow = flow;
  options.stallTimeoutSeconds = 5.0;
  return options;
}

}  // namespace

TEST_CASE("SerialSink delivers 200 KB in order, in uneven chunks", "[serial]") {
  auto flow = GENERATE(FlowControl::None, FlowControl::XonXoff);
  PtyPair pty;
  PtyPeer peer(pty);
  auto stream = lattice::testing::pseudoRandomBytes(200 * 1024, 1988);
  auto options = ptyOptions(pty, flow);
  SerialSink sink(SerialPort(options.port), options);
  std::mt19937 rng(7);
  std::size_t at = 0;
  while (at < stream.size()) {
    std::size_t n = std::min<std::size_t>(stream.size() - at, 1 + rng() % 9000);
    sink.write(std::span(stream).subspan(at, n));
    at += n;
  }
  sink.close();
  CHECK(sink.bytesWritten() == stream.size());
  REQUIRE(peer.waitFor(stream.size()));
  peer.settle(0.05);
  CHECK(peer.data() == stream);  // neither lost, repeated nor reordered; DC1/DC3 in the data pass as data
}

TEST_CASE("SerialSink --pace holds the rate to the baud rate", "[serial]") {
  PtyPair pty;
  PtyPeer peer(pty);
  auto options = ptyOptions(pty, FlowControl::None);
  options.baud = 19200;  // 1920 bytes/s at 8N1
  options.pace = true;
  auto stream = lattice::testing::pseudoRandomBytes(960, 3);
  SerialSink sink(SerialPort(options.port), options);
  auto start = std::chrono::steady_clock::now();
  sink.write(stream);
  sink.close();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Unpaced, a pty takes 960 bytes in well under a millisecond; paced they
  // need 0.5 s of line time, less the one burst of credit.
  CHECK(seconds > 0.4);
  REQUIRE(peer.waitFor(stream.size()));
  CHECK(peer.data() == stream);
}

TEST_CASE("SerialSink refuses writes after close", "[serial]") {
  PtyPair pty;
  auto options = ptyOptions(pty, FlowControl::None);
  SerialSink sink(SerialPort(options.port), options);
  sink.close();
  std::vector<std::uint8_t> byte{1};
  CHECK_THROWS_AS(sink.write(byte), Error);
}
