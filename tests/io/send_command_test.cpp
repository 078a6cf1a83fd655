// `lattice send` end to end: the built binary streams a file into a pty
// whose master side is the terminal. Needs the `lattice` target built
// (LATTICE_BINARY_DIR/app/lattice, or $LATTICE_EXE; test_io depends on it);
// the io-level behaviour is covered by flow_control_test.cpp as well.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "foundation/system/atomic_file.hpp"
#include "io/pty.hpp"
#include "tests/support/run_lattice.hpp"
#include "pty_peer.hpp"

using namespace lattice;
using namespace lattice::io;
using lattice::testing::PtyPeer;


TEST_CASE("lattice send streams a file to a pty, and resumes after a stall", "[send]") {
  // test_io depends on the `lattice` target (tests/CMakeLists.txt), so a
  // missing binary means a broken build: fail rather than skip quietly.
  INFO("lattice is not built (" << lattice::testing::latticeBinary() << "): build the `lattice` target or set LATTICE_EXE");
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  // Every byte value, to prove none is lost or changed: no terminal's stream, so --raw.
  auto stream = lattice::testing::pseudoRandomBytes(80 * 1024, 2024);
  auto file = std::filesystem::temp_directory_path() / fmt::format("lattice-send-test-{}.tek", ::getpid());
  writeFileAtomically(file, stream);

  PtyPair pty;
  PtyPeer peer(pty);
  peer.holdAt(20 * 1024);
  std::jthread terminal([&] { peer.stopSenderAt(20 * 1024); });
  auto stalled = lattice::testing::runLattice(fmt::format("send '{}' --port {} --baud 38400 --flow xonxoff --stall-timeout 0.5 --raw",
                                        file.string(), pty.slavePath()));
  terminal.join();
  CHECK(stalled.exitCode == 6);
  auto at = stalled.stderrText.find("--resume ");
  REQUIRE(at != std::string::npos);
  std::uint64_t resume = std::stoull(stalled.stderrText.substr(at + 9));
  peer.settle();
  CHECK(peer.received() == resume);
  CHECK(stalled.stderrText.find(fmt::format("lattice send {} --port {}", file.string(), pty.slavePath())) !=
        std::string::npos);
  CHECK(stalled.stderrText.find(fmt::format(" --raw --resume {}", resume)) != std::string::npos);  // --raw repeated

  peer.send(lattice::testing::kXon);
  auto resumed = lattice::testing::runLattice(fmt::format("send '{}' --port {} --baud 38400 --flow xonxoff --raw --resume {}",
                                        file.string(), pty.slavePath(), resume));
  CHECK(resumed.exitCode == 0);
  REQUIRE(peer.waitFor(stream.size()));
  peer.settle(0.05);
  CHECK(peer.data() == stream);

  auto pastEnd = lattice::testing::runLattice(fmt::format("send '{}' --port {} --raw --resume 999999999", file.string(), pty.slavePath()));
  CHECK(pastEnd.exitCode == 2);
  auto noPort = lattice::testing::runLattice(fmt::format("send '{}' --port /dev/lattice-no-such-tty --raw", file.string()));
  CHECK(noPort.exitCode == 5);
  CHECK(noPort.stderrText.find("no such serial port") != std::string::npos);
  auto noFile = lattice::testing::runLattice(fmt::format("send /nonexistent/lattice.tek --port {}", pty.slavePath()));
  CHECK(noFile.exitCode == 3);
  CHECK(noFile.stderrText.find("/nonexistent/lattice.tek") != std::string::npos);
  std::filesystem::remove(file);
}

namespace {

// A 4027 stream paced with `!REP 00` every 256 bytes or so, rendered by the
// real binary (so its requests sit where the driver put them).
std::vector<std::uint8_t> pacedTek4027Stream(const std::filesystem::path& file) {
  auto rendered = lattice::testing::runLattice(fmt::format(
      "render {}/scenes/sphere-hole.toml --width 64 --height 48 --device tek4027 --set pacing=report --set record-bytes=256 "
      "--stream '{}'",
      LATTICE_SOURCE_DIR, file.string()));
  INFO(rendered.stderrText);
  REQUIRE(rendered.exitCode == 0);
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::size_t> requestEnds(const std::vector<std::uint8_t>& stream) {
  const std::string text(stream.begin(), stream.end());
  std::vector<std::size_t> ends;
  for (auto at = text.find("!REP 00\r"); at != std::string::npos; at = text.find("!REP 00\r", at + 1))
    ends.push_back(at + 8);
  return ends;
}

}  // namespace

TEST_CASE("lattice send --device tek4027 sends one record per answer, and resumes after a silent terminal",
          "[send]") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  auto file = std::filesystem::temp_directory_path() / fmt::format("lattice-send-4027-{}.tek", ::getpid());
  const auto stream = pacedTek4027Stream(file);
  const std::vector<std::size_t> ends = requestEnds(stream);
  REQUIRE(ends.size() >= 4);
  REQUIRE(ends.back() == stream.size());

  SECTION("each record waits for the answer to the one before") {
    PtyPair pty;
    PtyPeer peer(pty);
    std::size_t overran = 0;
    std::jthread terminal([&] {
      for (std::size_t end : ends) {
        if (!peer.waitFor(end)) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(40));  // a sender that did not wait would be past `end`
        if (peer.received() != end) ++overran;
        for (char c : std::string("!DAT 00\r")) peer.send(static_cast<std::uint8_t>(c));
      }
    });
    auto sent = lattice::testing::runLattice(fmt::format("send '{}' --port {} --baud 38400 --device tek4027 --stall-timeout 5",
                                                         file.string(), pty.slavePath()));
    terminal.join();
    INFO(sent.stderrText);
    CHECK(sent.exitCode == 0);
    CHECK(overran == 0);
    peer.settle(0.05);
    CHECK(peer.data() == stream);
    CHECK(sent.stderrText.find(fmt::format("after each of {} records", ends.size())) != std::string::npos);
  }

  SECTION("a terminal that stops answering: exit 6 and a resume command that keeps --device") {
    PtyPair pty;
    PtyPeer peer(pty);
    std::jthread terminal([&] {  // answers the first two requests only
      for (std::size_t i = 0; i < 2; ++i) {
        if (!peer.waitFor(ends[i])) return;
        for (char c : std::string("!DAT 00\r")) peer.send(static_cast<std::uint8_t>(c));
      }
    });
    auto stalled = lattice::testing::runLattice(fmt::format(
        "send '{}' --port {} --baud 38400 --device tek4027 --stall-timeout 0.5", file.string(), pty.slavePath()));
    terminal.join();
    INFO(stalled.stderrText);
    CHECK(stalled.exitCode == 6);
    CHECK(stalled.stderrText.find("did not answer request 3 of") != std::string::npos);
    CHECK(stalled.stderrText.find(fmt::format("--device tek4027 --resume {}", ends[2])) != std::string::npos);
    peer.settle(0.05);
    CHECK(peer.received() == ends[2]);  // nothing of record 4 went out
  }

  SECTION("without --device the send goes straight through and says what it did not do") {
    PtyPair pty;
    PtyPeer peer(pty);
    auto sent = lattice::testing::runLattice(fmt::format("send '{}' --port {} --baud 38400", file.string(), pty.slavePath()));
    INFO(sent.stderrText);
    CHECK(sent.exitCode == 0);
    REQUIRE(peer.waitFor(stream.size()));
    CHECK(sent.stderrText.find(fmt::format("holds {} report requests", ends.size())) != std::string::npos);
    CHECK(sent.stderrText.find("add --device tek4027") != std::string::npos);
  }
  std::filesystem::remove(file);
}
