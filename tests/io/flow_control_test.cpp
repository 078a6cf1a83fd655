// XON/XOFF through a pty: the slave's line discipline applies IXON to what
// is written into the slave, so the peer's DC3 on the master stops the sink
// and DC1 restarts it (verified on Linux; docs/serial.md).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "io/pty.hpp"
#include "io/serial_port.hpp"
#include "io/serial_sink.hpp"
#include "io/stream_sender.hpp"
#include "pty_peer.hpp"

using namespace lattice;
using namespace lattice::io;
using lattice::testing::kXoff;
using lattice::testing::kXon;
using lattice::testing::PtyPeer;

namespace {

SerialOptions xonxoff(const PtyPair& pty, double stallSeconds) {
  SerialOptions options;
  options.port = pty.slavePath();
  options.baud = 38400;
  options.flow = FlowControl::XonXoff;
  options.stallTimeoutSeconds = stallSeconds;
  return options;
}

}  // namespace

TEST_CASE("XOFF mid-stream pauses the sink, XON resumes it, nothing lost or repeated", "[serial][flow]") {
  PtyPair pty;
  PtyPeer peer(pty);
  auto stream = lattice::testing::pseudoRandomBytes(300 * 1024, 42);
  auto options = xonxoff(pty, 5.0);
  SerialSink sink(SerialPort(options.port), options);

  std::size_t heldAt = 0, afterPause = 0;
  peer.holdAt(64 * 1024);
  std::jthread terminal([&] {
    if (!peer.stopSenderAt(64 * 1024)) return;
    peer.settle(0.1);  // bytes already in the pty buffer still arrive
    heldAt = peer.received();
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    afterPause = peer.received();
    peer.send(kXon);
  });
  sendStream(stream, 0, sink);
  terminal.join();

  CHECK(heldAt < stream.size());
  CHECK(afterPause == heldAt);  // the line was really held during the pause
  CHECK_FALSE(peer.outputStopped());  // and XON restarted it
  REQUIRE(peer.waitFor(stream.size()));
  peer.settle(0.05);
  CHECK(peer.data() == stream);
}

TEST_CASE("A peer that never sends XON stalls the sink, and resuming from the offset completes the stream",
          "[serial][flow]") {
  PtyPair pty;
  PtyPeer peer(pty);
  auto stream = lattice::testing::pseudoRandomBytes(150 * 1024, 7);
  auto options = xonxoff(pty, 0.5);

  bool stopped = false;
  peer.holdAt(40 * 1024);
  std::jthread terminal([&] { stopped = peer.stopSenderAt(40 * 1024); });
  std::uint64_t resumeAt = 0;
  {
    SerialSink sink(SerialPort(options.port), options);
    try {
      sendStream(stream, 0, sink);
      terminal.join();
      FAIL("the send should have stalled; the peer got " << peer.received() << " bytes");
    } catch (const SerialFault& fault) {
      CHECK(fault.kind() == ErrorKind::Stalled);
      CHECK(fault.exitCode() == 6);
      resumeAt = fault.resumeOffset();
      CHECK(std::string(fault.what()).find(fmt::format("resume from offset {}", resumeAt)) != std::string::npos);
    }
  }
  terminal.join();
  REQUIRE(stopped);
  peer.settle();
  // Exactly the bytes before the resume offset reached the terminal.
  REQUIRE(peer.received() == resumeAt);
  CHECK(resumeAt >= 40 * 1024);
  CHECK(resumeAt < stream.size());

  // The operator clears the terminal (XON) and runs the printed --resume.
  peer.send(kXon);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  SerialSink resumed(SerialPort(options.port), options);
  auto result = sendStream(stream, resumeAt, resumed);
  CHECK(result.bytesSent == stream.size() - resumeAt);
  REQUIRE(peer.waitFor(stream.size()));
  peer.settle(0.05);
  CHECK(peer.data() == stream);  // first part + resumed part, nothing twice
}

TEST_CASE("A stop check ends a send held by XOFF at once, counting exactly what went out", "[serial][flow]") {
  // What Ctrl-C does to `lattice send` (SendSignals): the held line would
  // otherwise wait out the 30 s stall timeout.
  PtyPair pty;
  PtyPeer peer(pty);
  auto stream = lattice::testing::pseudoRandomBytes(150 * 1024, 11);
  auto options = xonxoff(pty, 30.0);
  std::atomic<bool> stop{false};
  bool held = false;
  peer.holdAt(40 * 1024);
  std::jthread terminal([&] {
    held = peer.stopSenderAt(40 * 1024);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the sender waits on the held line
    stop = true;
  });
  std::uint64_t resumeAt = 0;
  const auto start = std::chrono::steady_clock::now();
  {
    SerialSink sink(SerialPort(options.port), options);
    sink.setStopCheck([&] { return stop.load(); });
    try {
      sendStream(stream, 0, sink);
      FAIL("the send should have stopped; the peer got " << peer.received() << " bytes");
    } catch (const SendStopped& stopped) {
      resumeAt = stopped.resumeOffset();
      CHECK(stopped.acceptedOffset() >= resumeAt);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  terminal.join();
  REQUIRE(held);
  CHECK(seconds < 5.0);  // not the stall timeout
  peer.send(kXon);
  peer.settle();
  // Nothing queued trickled out after the count: the peer has exactly the bytes before the offset.
  REQUIRE(peer.received() == resumeAt);
  CHECK(resumeAt >= 40 * 1024);
  CHECK(resumeAt < stream.size());
  const std::vector<std::uint8_t> got = peer.data();
  CHECK(std::equal(got.begin(), got.end(), stream.begin()));
}

TEST_CASE("A stall reports offsets in the whole stream when the send itself was a resume", "[serial][flow]") {
  PtyPair pty;
  PtyPeer peer(pty);
  auto stream = lattice::testing::pseudoRandomBytes(64 * 1024, 9);
  auto options = xonxoff(pty, 0.3);
  SerialSink sink(SerialPort(options.port), options);
  // Held from the start. (Sent after the port is configured: opening
  // restarts a line left stopped by an XOFF nobody was there to see.)
  peer.send(kXoff);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  try {
    sendStream(stream, 1000, sink);
    FAIL("the send should have stalled");
  } catch (const SerialFault& fault) {
    CHECK(fault.kind() == ErrorKind::Stalled);
    CHECK(fault.resumeOffset() == 1000);
    CHECK(peer.received() == 0);
  }
}

TEST_CASE("Opening the port voids an XOFF sent before it was opened", "[serial][flow]") {
  PtyPair pty;
  PtyPeer peer(pty);
  auto options = xonxoff(pty, 0.5);
  { SerialSink earlier(SerialPort(options.port), options); }
  peer.send(kXoff);  // the terminal was busy while nobody had the port open
  REQUIRE(peer.waitForStop());
  auto stream = lattice::testing::pseudoRandomBytes(32 * 1024, 5);
  SerialSink sink(SerialPort(options.port), options);
  sendStream(stream, 0, sink);  // would stall without the restart on open
  REQUIRE(peer.waitFor(stream.size()));
  peer.settle(0.05);
  CHECK(peer.data() == stream);
}

TEST_CASE("A peer that hangs up mid-stream gives a HangUp error with the byte counts", "[serial][flow]") {
  PtyPair pty;
  auto peer = std::make_unique<PtyPeer>(pty);
  auto stream = lattice::testing::pseudoRandomBytes(400 * 1024, 11);
  auto options = xonxoff(pty, 5.0);
  SerialSink sink(SerialPort(options.port), options);
  std::size_t peerGot = 0;
  bool reached = false;
  peer->holdAt(50 * 1024);  // a busy terminal: the pty fills and the sender blocks
  std::jthread terminal([&] {
    reached = peer->waitFor(50 * 1024);
    peer->stop();
    peerGot = peer->received();
    pty.closeMaster();
  });
  try {
    sendStream(stream, 0, sink);
    terminal.join();
    CHECK(reached);
    FAIL("the send should have hit the hang-up");
  } catch (const SerialFault& fault) {
    terminal.join();
    CHECK(fault.kind() == ErrorKind::HangUp);
    CHECK(fault.exitCode() == 7);
    // Bytes the pty accepted but the peer never read are lost with it: the
    // offset is what left our side, never less than what the peer saw.
    CHECK(fault.resumeOffset() >= peerGot);
    CHECK(fault.resumeOffset() < stream.size());
    CHECK(std::string(fault.what()).find("hung up") != std::string::npos);
  }
}
