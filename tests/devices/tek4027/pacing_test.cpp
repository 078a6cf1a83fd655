// Report pacing: the stream cut into records that each end with `!REP 00`,
// and a driver that waits for the terminal's answer after each record, over
// a real pty (tests/io/pty_peer.hpp) standing in for the serial line: the
// driver on its own, and the `lattice render --port` command.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "io/pty.hpp"
#include "io/serial_port.hpp"
#include "io/serial_sink.hpp"
#include "tests/devices/tek4027/drive_frame.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/io/pty_peer.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::tek4027;
using namespace lattice::tek4027::test;

namespace {

using test::feedFrame;

std::string drive(const IndexedImage& img, const Tek4027Profile& profile) { return test::driveFrame(img, profile); }

Tek4027Profile alwaysPaced() {
  Tek4027Profile profile;
  profile.pacing = Tek4027Pacing::Report;
  return profile;
}

// A paced driver on the slave side of a pty (the serial line), the peer on
// the master side as the terminal, and the driver reading answers from the line.
struct PacedLine {
  explicit PacedLine(double replyTimeout) : replies(sink.fd(), replyTimeout) { driver.setReplies(&replies); }
  static SerialOptions options(const PtyPair& pty) {
    SerialOptions o;
    o.port = pty.slavePath();
    o.baud = 38400;
    o.flow = FlowControl::XonXoff;
    o.stallTimeoutSeconds = 5.0;
    return o;
  }
  PtyPair pty;
  testing::PtyPeer peer{pty};
  SerialSink sink{SerialPort(pty.slavePath()), options(pty)};
  Tek4027Profile profile = alwaysPaced();
  Tek4027FdReplies replies;
  Tek4027Driver driver{sink, profile};
};

IndexedImage decodeScreen(const std::string& text, const Tek4027Profile& profile) {
  Tek4027Decoder d(profile);
  d.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  d.finish();
  REQUIRE(d.report().malformed == 0);
  REQUIRE(d.report().unknownCommands == 0);
  return d.image();
}

}  // namespace

TEST_CASE("records end with a report request and hold whole commands") {
  const Tek4027Profile paced = alwaysPaced();
  Tek4027Profile plain = paced;
  plain.pacing = Tek4027Pacing::None;
  const auto img = testing::ringsImage(160, 120);
  const std::string text = drive(img, paced);
  const std::vector<std::size_t> ends = reportRecordEnds(text, paced);
  REQUIRE(ends.size() > 3);
  CHECK(ends.back() == text.size());  // the last request ends the stream
  std::size_t start = 0;
  for (std::size_t end : ends) {
    CHECK(end - start <= static_cast<std::size_t>(paced.recordBytes));
    CHECK(text[start] == '!');  // a record starts with a command
    start = end;
  }
  // Same picture with and without the requests.
  CHECK(decodeScreen(text, paced).pixels == decodeScreen(drive(img, plain), plain).pixels);
}

TEST_CASE("auto pacing leaves a stream of one record alone") {
  const Tek4027Profile profile;  // strict: auto
  IndexedImage small(8, 8, 2);
  small.colormap = {{0, 0, 0}, {255, 255, 255}};
  small.at(3, 3) = 1;
  const std::string text = drive(small, profile);
  CHECK(text.size() <= static_cast<std::size_t>(profile.recordBytes));
  CHECK(text.find("!REP") == std::string::npos);
}

TEST_CASE("over a serial line the driver waits for each answer before the next record", "[serial]") {
  PacedLine line(5.0);
  testing::PtyPeer& peer = line.peer;
  const auto img = testing::ringsImage(160, 120);
  const std::string expected = drive(img, line.profile);
  const std::vector<std::size_t> ends = reportRecordEnds(expected, line.profile);
  REQUIRE(ends.size() > 3);

  std::thread sender([&] { feedFrame(line.driver, img); });
  // The terminal: after each record, make sure nothing more arrives until it
  // answers, then answer with a report line.
  std::size_t overran = 0;
  for (std::size_t end : ends) {
    REQUIRE(peer.waitFor(end));
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    if (peer.received() != end) ++overran;
    for (char c : std::string("!DAT 00\r")) peer.send(static_cast<std::uint8_t>(c));
  }
  sender.join();
  line.sink.close();
  peer.settle(0.05);
  CHECK(overran == 0);
  CHECK(line.replies.repliesSeen() == ends.size());
  const auto got = peer.data();
  CHECK(std::string(got.begin(), got.end()) == expected);  // the same bytes as the file path
}

TEST_CASE("a terminal that never answers stops the paced driver with Stalled", "[serial]") {
  PacedLine line(0.3);
  try {
    feedFrame(line.driver, testing::ringsImage(160, 120));
    FAIL("the driver went on without an answer");
  } catch (const lattice::Error& e) {
    CHECK(e.kind() == ErrorKind::Stalled);
  }
  // It stopped after the first record.
  const std::string expected = drive(testing::ringsImage(160, 120), line.profile);
  line.peer.settle(0.05);
  CHECK(line.peer.received() == reportRecordEnds(expected, line.profile).front());
}

TEST_CASE("lattice render --port waits for each answer and sends the bytes --stream writes", "[serial]") {
  // Built with test_devices_tek4027 (tests/CMakeLists.txt): a missing binary
  // is a broken build, not a reason to skip.
  INFO("binary " << testing::latticeBinary().string() << " (build the `lattice` target, or set LATTICE_EXE)");
  REQUIRE(std::filesystem::exists(testing::latticeBinary()));
  const std::string scene = testing::sourcePath("scenes/torus-floor.toml").string();
  const std::string common = fmt::format("render '{}' --device tek4027 --width 120 --height 90", scene);
  const auto file = std::filesystem::temp_directory_path() / fmt::format("paced-{}.t27", ::getpid());
  const testing::CommandRun toFile = testing::runLattice(fmt::format("{} --stream '{}'", common, file.string()));
  INFO("--stream run: " << toFile.stderrText);
  REQUIRE(toFile.exitCode == 0);
  std::ifstream in(file, std::ios::binary);
  const std::string expected((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(file);
  const std::vector<std::size_t> ends = reportRecordEnds(expected, Tek4027Profile{});
  REQUIRE(ends.size() > 3);  // strict paces a stream longer than one record

  PtyPair pty;
  testing::PtyPeer peer(pty);
  testing::CommandRun toPort;
  // render --port records the stream before sending it: into the temporary folder, not the working one.
  const auto recording = std::filesystem::temp_directory_path() / fmt::format("paced-port-{}.t27", ::getpid());
  std::thread sender([&] {
    toPort = testing::runLattice(fmt::format("{} --port {} --baud 38400 --stall-timeout 10 --stream '{}'", common,
                                             pty.slavePath(), recording.string()));
  });
  std::size_t overran = 0;
  for (std::size_t end : ends) {
    if (!peer.waitFor(end, 20.0)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (peer.received() != end) ++overran;
    for (char c : std::string("!DAT 00\r")) peer.send(static_cast<std::uint8_t>(c));
  }
  sender.join();
  INFO("--port run: " << toPort.stderrText);
  CHECK(toPort.exitCode == 0);
  peer.settle(0.05);
  CHECK(overran == 0);
  const auto got = peer.data();
  CHECK(std::string(got.begin(), got.end()) == expected);
  std::filesystem::remove(recording);
}
