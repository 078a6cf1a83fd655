// `lattice term` end to end, the real binary with real peers: a stream
// played, programs on its pseudo-terminal (gnuplot's tek410x and tek40xx
// terminals, plotutils' `graph -T tek`, a shell that kills itself), a serial
// line that hangs up, and the user's terminal played by a pty
// (tests/support/pty_host.hpp): raw while running, restored on every way
// out, sixels drawn where the terminal says it shows them. Every session's
// snapshot must equal `lattice emulate` of its recording.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/png.hpp"
#include "io/pty.hpp"
#include "tests/support/pty_host.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/sixel_screen.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::runLattice;

namespace {

const std::string kPlate = std::string(LATTICE_GOLDEN_DIR) + "/tek4125/scenes/torus-floor_80x60_8planes.tek";

bool onPath(const char* program) {
  return std::system(fmt::format("command -v {} >/dev/null 2>&1", program).c_str()) == 0;
}

// The snapshot equals `lattice emulate` of the recording, and is not blank.
void requireSnapshotIsRecording(const lattice::testing::TempDir& scratch, const std::string& device) {
  const auto run = runLattice(fmt::format("emulate --device {} --raw '{}' -o '{}'", device, scratch / "r.tek",
                                          scratch / "e.png"));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  const lattice::RgbImage snapshot = lattice::io::readPng(scratch / "s.png");
  const lattice::RgbImage emulated = lattice::io::readPng(scratch / "e.png");
  CHECK(snapshot.rgb == emulated.rgb);
  CHECK(std::any_of(snapshot.rgb.begin(), snapshot.rgb.end(), [](std::uint8_t v) { return v != 0; }));
}

}  // namespace

TEST_CASE("term --stream: the recording is the stream, the snapshot its screen", "[term]") {
  const lattice::testing::TempDir scratch("term-stream");
  const auto run = runLattice(fmt::format("term --stream '{}' --unpaced --snapshot '{}' --record '{}'", kPlate,
                                          scratch / "s.png", scratch / "r.tek"));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  CHECK_THAT(run.stderrText, Catch::Contains("no display") && Catch::Contains("the stream has been played"));
  CHECK(lattice::readWholeFile(scratch / "r.tek") == lattice::readWholeFile(kPlate));
  requireSnapshotIsRecording(scratch, "tek4125");
}

TEST_CASE("term --stream plays at the line rate", "[term]") {
  // 9600 baud is 960 characters a second: the stream's bytes take that long.
  const lattice::testing::TempDir scratch("term-paced");
  const std::vector<std::uint8_t> bytes = lattice::readWholeFile(kPlate);
  const std::string part = scratch / "part.tek";
  lattice::writeFileAtomically(part, std::span(bytes).first(1920));
  const auto start = std::chrono::steady_clock::now();
  const auto run = runLattice(fmt::format("term --stream '{}' --baud 9600 --record '{}'", part, scratch / "r.tek"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(run.exitCode == 0);
  CHECK(seconds >= 1.9);  // a lower bound only: the pacing, not a speed target
}

TEST_CASE("term runs gnuplot's tek410x and tek40xx terminals, the screen emulate of the recording", "[term]") {
  if (!onPath("gnuplot")) {
    WARN("gnuplot is not installed: skipped (scripts/setup.sh installs gnuplot-nox)");
    return;
  }
  struct Case {
    const char* terminal;
    const char* device;
  };
  for (const Case c : {Case{"tek410x", "tek4125"}, Case{"tek40xx", "tek4014"}}) {
    const lattice::testing::TempDir scratch("term-gnuplot");
    const std::string plot = fmt::format("set term {}; plot sin(x), cos(x)", c.terminal);
    auto run = runLattice(fmt::format("term --device {} --snapshot '{}' --record '{}' -- gnuplot -e '{}'", c.device,
                                      scratch / "s.png", scratch / "r.tek", plot));
    INFO(c.terminal << ": " << run.stderrText);
    REQUIRE(run.exitCode == 0);
    CHECK_THAT(run.stderrText, Catch::Contains("gnuplot exited with status 0"));
    requireSnapshotIsRecording(scratch, c.device);
    // Byte for byte what gnuplot writes to a file: the pty changed nothing (no CR added to LF).
    REQUIRE(std::system(fmt::format("gnuplot -e 'set output \"{}\"; {}'", scratch / "file.tek", plot).c_str()) == 0);
    CHECK(lattice::readWholeFile(scratch / "r.tek") == lattice::readWholeFile(scratch / "file.tek"));
  }
}

TEST_CASE("term runs plotutils' graph -T tek on the 4014", "[term]") {
  if (!onPath("graph")) {
    WARN("plotutils (graph) is not installed: skipped (scripts/setup.sh --terminals installs it)");
    return;
  }
  const lattice::testing::TempDir scratch("term-graph");
  const auto run = runLattice(fmt::format(
      "term --device tek4014 --snapshot '{}' --record '{}' -- sh -c 'printf \"0 0\\n1 1\\n2 0\\n3 1\\n\" | graph -T tek'",
      scratch / "s.png", scratch / "r.tek"));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  CHECK_THAT(run.stderrText, Catch::Contains("exited with status 0"));
  CHECK(lattice::readWholeFile(scratch / "r.tek").size() > 100);
  requireSnapshotIsRecording(scratch, "tek4014");
}

TEST_CASE("term: a program that is killed leaves the terminal restored, the recording and snapshot whole", "[term]") {
  const lattice::testing::TempDir scratch("term-killed");
  lattice::testing::PtyHost host(24, 80, 0, 0, false);
  host.start({"term", "--snapshot", scratch / "s.png", "--record", scratch / "r.tek", "--", "sh", "-c",
              fmt::format("cat '{}'; sleep 0.5; kill -9 $$", kPlate)});
  CHECK(host.wait(20) == 0);
  INFO(host.output());
  CHECK_THAT(host.output(), Catch::Contains("was killed by signal 9"));
  CHECK(host.sawRaw());
  CHECK(host.restored());
  CHECK(lattice::readWholeFile(scratch / "r.tek") == lattice::readWholeFile(kPlate));
  requireSnapshotIsRecording(scratch, "tek4125");
}

TEST_CASE("term: SIGTERM and the quit key end the session like the program's end, the PNG key writes the screen", "[term]") {
  for (const bool quitKey : {false, true}) {
    const lattice::testing::TempDir scratch("term-signal");
    lattice::testing::PtyHost host(24, 80, 0, 0, false);
    host.start({"term", "--snapshot", scratch / "s.png", "--record", scratch / "r.tek", "--png-prefix",
                scratch / "key", "--", "sh", "-c", fmt::format("cat '{}'; sleep 60", kPlate)});
    // Until the whole stream has arrived and been drawn (the snapshot's last rewrite).
    for (int i = 0; i < 100 && !(std::filesystem::exists(scratch / "s.png") && host.sawRaw()); ++i) host.pump(0.1);
    host.pump(0.5);
    if (quitKey) {
      host.type("\x1c");  // the PNG key first
      host.pump(0.5);
      host.type("\x1d");
    } else {
      host.signal(SIGTERM);
    }
    CHECK(host.wait(20) == 0);
    INFO(host.output());
    CHECK_THAT(host.output(), Catch::Contains(quitKey ? "the quit key" : "stopped by SIGTERM"));
    CHECK(host.sawRaw());
    CHECK(host.restored());
    CHECK(lattice::readWholeFile(scratch / "r.tek") == lattice::readWholeFile(kPlate));
    requireSnapshotIsRecording(scratch, "tek4125");
    if (quitKey) {
      CHECK_THAT(host.output(), Catch::Contains("wrote " + scratch / "key-1.png"));
      CHECK(lattice::io::readPng(scratch / "key-1.png").rgb == lattice::io::readPng(scratch / "s.png").rgb);
    }
  }
}

TEST_CASE("term --port: a line that hangs up ends the session with the recording and snapshot whole", "[term]") {
  const lattice::testing::TempDir scratch("term-hangup");
  lattice::io::PtyPair line;
  // A look at the line's input queue (FIONREAD), opened before the terminal takes the line exclusively.
  const int queue = ::open(line.slavePath().c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
  REQUIRE(queue >= 0);
  lattice::testing::PtyHost host(24, 80, 0, 0, false);
  host.start({"term", "--port", line.slavePath(), "--baud", "38400", "--snapshot", scratch / "s.png", "--record",
              scratch / "r.tek"});
  line.releaseSlave();
  // Until the terminal has set the line up (raw): before that the pty's cooked
  // line discipline would edit the bytes (DEL erases, ^U kills a line).
  termios mode{};
  for (int i = 0; i < 400 && ::tcgetattr(queue, &mode) == 0 && (mode.c_lflag & ICANON); ++i) host.pump(0.025);
  REQUIRE(!(mode.c_lflag & ICANON));
  // And has asked the host for sixels (in vain, a second): its loop is reading the line.
  for (int i = 0; i < 100 && host.output().find("no display") == std::string::npos; ++i) host.pump(0.05);
  const std::vector<std::uint8_t> bytes = lattice::readWholeFile(kPlate);
  std::atomic<bool> written{false};
  std::thread writer([&] {
    // In two halves with a pause between: a quiet line is not a hung-up one.
    const std::size_t half = bytes.size() / 2;
    (void)!::write(line.masterFd(), bytes.data(), half);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    (void)!::write(line.masterFd(), bytes.data() + half, bytes.size() - half);
    written = true;
  });
  // Until every byte has been taken off the line: a hang-up throws away what is still queued.
  int queued = 1;
  for (int i = 0; i < 800 && !(written && queued == 0); ++i) {
    host.pump(0.025);
    ::ioctl(queue, FIONREAD, &queued);
  }
  writer.join();
  host.pump(0.2);
  ::close(queue);
  line.closeMaster();  // the hang-up
  CHECK(host.wait(20) == 0);
  INFO(host.output());
  CHECK_THAT(host.output(), Catch::Contains("hung up"));
  CHECK(host.restored());
  CHECK(lattice::readWholeFile(scratch / "r.tek") == bytes);
  requireSnapshotIsRecording(scratch, "tek4125");
}

TEST_CASE("term draws the screen as sixels in a terminal that says it shows them", "[term]") {
  const lattice::testing::TempDir scratch("term-sixel");
  // 100 x 40 cells of 10 x 20 pixels: the 1280 x 1024 screen is shown at 925 x 740.
  lattice::testing::PtyHost host(40, 100, 1000, 800, true);
  host.start({"term", "--stream", kPlate, "--unpaced", "--snapshot", scratch / "s.png"});
  CHECK(host.wait(20) == 0);
  const std::string& out = host.output();
  INFO(out.substr(out.size() > 400 ? out.size() - 400 : 0));
  CHECK(out.find("no display") == std::string::npos);
  CHECK_THAT(out, Catch::Contains("Ctrl-] quits"));
  const lattice::testing::SixelScreen shown = lattice::testing::composeSixels(out, 925, 740, 20);
  REQUIRE(shown.pictures >= 1);
  // What the host shows is the snapshot scaled by nearest neighbour, each
  // gun within the sixel's whole-percent rounding.
  const lattice::RgbImage snapshot = lattice::io::readPng(scratch / "s.png");
  int worst = 0;
  for (int y = 0; y < 740; ++y)
    for (int x = 0; x < 925; ++x) {
      const std::uint8_t* want = snapshot.pixel(x * 1280 / 925, y * 1024 / 740);
      const std::uint8_t* got = shown.image.pixel(x, y);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(want[c]) - int(got[c])));
    }
  CHECK(worst <= 2);
  CHECK(host.restored());
}

TEST_CASE("term fits the picture again when the window changes size", "[term]") {
  const lattice::testing::TempDir scratch("term-resize");
  lattice::testing::PtyHost host(40, 100, 1000, 800, true);
  host.start({"term", "--snapshot", scratch / "s.png", "--", "sh", "-c", fmt::format("cat '{}'; sleep 3", kPlate)});
  for (int i = 0; i < 100 && host.output().find("\"1;1;925;") == std::string::npos; ++i) host.pump(0.05);
  REQUIRE(host.output().find("\"1;1;925;") != std::string::npos);  // drawn at 925 x 740 in 100 x 40 cells
  host.pump(0.3);
  host.resize(30, 60, 600, 600);  // 60 x 30 cells of 10 x 20: 600 x 540 above the text rows
  CHECK(host.wait(20) == 0);
  INFO(host.output().substr(host.output().size() > 300 ? host.output().size() - 300 : 0));
  // Fitted again: 1280 x 1024 into 600 x 540 is 600 x 480, drawn whole from the top.
  CHECK(host.output().find("\x1b[1;1H\x1bPq\"1;1;600;480") != std::string::npos);
  CHECK(host.restored());
}

TEST_CASE("term: usage errors name the fix", "[term][cli]") {
  auto run = runLattice("term");
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::Contains("exactly one of"));
  run = runLattice(fmt::format("term --stream '{}' -- true", kPlate));
  CHECK(run.exitCode == 2);
  run = runLattice("term -- /nonexistent/program");
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::Contains("cannot run /nonexistent/program"));
  run = runLattice("term --stream /nonexistent.tek");
  CHECK(run.exitCode == 2);
  run = runLattice(fmt::format("term --stream '{}' --refresh 0", kPlate));
  CHECK(run.exitCode == 2);
}

TEST_CASE("term --device tek4027 answers lattice send's report requests across a line", "[term][serial]") {
  // Two pseudo-terminals bridged by this test, master to master, as a null-modem cable joins
  // two serial ports: `lattice send` on one, `lattice term --port` on the other. send stops at
  // every `!REP 00` of the 4027's strict stream until the terminal's CR comes back.
  const lattice::testing::TempDir scratch("term-4027");
  const std::string stream = scratch / "hole.t27";
  auto run = runLattice(fmt::format("render '{}/scenes/sphere-hole.toml' --width 96 --height 72 --device tek4027 "
                                    "--stream '{}' -q", LATTICE_SOURCE_DIR, stream));
  REQUIRE(run.exitCode == 0);
  const std::vector<std::uint8_t> bytes = lattice::readWholeFile(stream);
  const std::size_t requests = lattice::devices::makeDevice("tek4027").replies->points(bytes).size();
  REQUIRE(requests > 1);

  lattice::io::PtyPair sender, terminal;  // each keeps its own slave open: no EIO while a side is closed
  std::atomic<bool> stop{false};
  std::thread cable([&] {
    const int a = sender.masterFd(), b = terminal.masterFd();
    // Writes never block: a far side that is slow to read (a loaded machine)
    // must not keep the cable from seeing `stop`, or the test would hang.
    for (const int fd : {a, b}) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    const auto pass = [&](int to, const char* data, ssize_t n) {
      while (n > 0 && !stop) {
        const ssize_t put = ::write(to, data, static_cast<std::size_t>(n));
        if (put > 0) {
          data += put, n -= put;
        } else {
          pollfd room{to, POLLOUT, 0};
          ::poll(&room, 1, 20);
        }
      }
    };
    char buffer[4096];
    while (!stop) {
      pollfd p[2] = {{a, POLLIN, 0}, {b, POLLIN, 0}};
      ::poll(p, 2, 20);
      ssize_t n;
      if ((p[0].revents & POLLIN) && (n = ::read(a, buffer, sizeof buffer)) > 0) pass(b, buffer, n);
      if ((p[1].revents & POLLIN) && (n = ::read(b, buffer, sizeof buffer)) > 0) pass(a, buffer, n);
    }
  });
  lattice::testing::CommandRun term;
  std::thread termThread([&] {
    term = runLattice(fmt::format("term --device tek4027 --port '{}' --baud 9600 --record '{}' --snapshot '{}'",
                                  terminal.slavePath(), scratch / "r.tek", scratch / "s.png"));
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the terminal opens its line
  run = runLattice(fmt::format("send '{}' --device tek4027 --port '{}' --baud 9600 --stall-timeout 20", stream,
                               sender.slavePath()));
  INFO(run.stderrText);
  CHECK(run.exitCode == 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the last bytes cross
  stop = true;  // the cable is unplugged before its descriptor closes (a closed number is soon reused)
  cable.join();
  terminal.closeMaster();  // the line hangs up: the session ends
  termThread.join();
  INFO("term exit " << term.exitCode << ": " << term.stderrText);
  REQUIRE(term.exitCode == 0);
  CHECK_THAT(term.stderrText, Catch::Contains(fmt::format("{} bytes received, {} answers sent", bytes.size(), requests)));
  CHECK(lattice::readWholeFile(scratch / "r.tek") == bytes);
  requireSnapshotIsRecording(scratch, "tek4027");
}
