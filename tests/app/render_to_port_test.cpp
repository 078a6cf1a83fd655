// One command from scene to screen: `lattice render SCENE --device tek4125
// --port virtual:tek4125 --wire-seconds S` renders, fits the picture (and
// its size) to the budget, records the stream and sends it to our emulator
// on a pseudo-terminal. The real binary against a real pty: the screen the
// virtual terminal drew must be what `emulate` draws from the recording, and
// one baud must be counted everywhere.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <regex>

#include "io/png.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::runLattice;

TEST_CASE("render --port virtual:tek4125 --wire-seconds: one command takes a scene to the virtual terminal", "[serial]") {
  const lattice::testing::TempDir scratch("render-to-port");
  const std::string scene = lattice::testing::sourcePath("scenes/sphere-hole.toml").string();
  const std::string screen = scratch / "screen.png";
  // A small drawable area keeps the size search short; 9600 baud through --set alone.
  const auto run = runLattice(fmt::format("render '{}' --device tek4125 --set width=160 --set height=120 --set "
                                          "baud=9600 --port virtual:tek4125 --wire-seconds 2 -o '{}' -q",
                                          scene, screen));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  // The recording lies beside the picture, named for the device, and fits 2 s at 9600 baud (8N1).
  const std::string recording = scratch / "screen.tek4125";
  REQUIRE(std::filesystem::exists(recording));
  CHECK(std::filesystem::file_size(recording) <= 1920);
  CHECK_THAT(run.stderrText, Catch::Contains(fmt::format("the stream is recorded in {}", recording)));
  // The size was searched (no --width/--height) and reported.
  CHECK_THAT(run.stderrText, Catch::Contains("wire budget: picture ") && Catch::Contains("sizes tried:"));
  // One baud: the budget, the timing line and the virtual terminal's line.
  CHECK_THAT(run.stderrText, Catch::Contains("at 9600 baud") && !Catch::Contains("38400"));
  CHECK_THAT(run.stderrText, Catch::Contains("a virtual Tektronix 4125 at 9600 baud"));
  // What arrived is what the recording draws.
  const std::string emulated = scratch / "emulated.png";
  const auto emulate = runLattice(fmt::format(
      "emulate --device tek4125 --set width=160 --set height=120 '{}' -o '{}'", recording, emulated));
  REQUIRE(emulate.exitCode == 0);
  const lattice::RgbImage sent = lattice::io::readPng(screen), drawn = lattice::io::readPng(emulated);
  CHECK(sent.width == drawn.width);
  CHECK(sent.height == drawn.height);
  CHECK((sent.rgb == drawn.rgb));  // not printed: a screen's worth of bytes
  // The recording resumes as any stream does: the second half to a fresh terminal.
  const std::uint64_t half = std::filesystem::file_size(recording) / 2;
  const auto resumed = runLattice(fmt::format("send '{}' --port virtual:tek4125 --set baud=9600 --resume {} -o '{}'",
                                              recording, half, std::string(scratch / "rest.png")));
  INFO(resumed.stderrText);
  CHECK(resumed.exitCode == 0);
  CHECK_THAT(resumed.stderrText, Catch::Contains(fmt::format("sent {} bytes", std::filesystem::file_size(recording) - half)));
}

TEST_CASE("render --port with --stream records there, and --stream - with --port is refused", "[serial]") {
  const lattice::testing::TempDir scratch("render-to-port-stream");
  const std::string scene = lattice::testing::sourcePath("scenes/sphere-hole.toml").string();
  const std::string stream = scratch / "hole.tek";
  const auto run = runLattice(fmt::format(
      "render '{}' --device tek4125 --width 48 --height 48 --port virtual:tek4125 --stream '{}' -o '{}' -q", scene,
      stream, std::string(scratch / "s.png")));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  CHECK(std::filesystem::exists(stream));
  CHECK_FALSE(std::filesystem::exists(scratch / "s.tek4125"));
  CHECK_THAT(run.stderrText, !Catch::Contains("sizes tried"));  // no budget, no search

  const auto refused = runLattice(fmt::format(
      "render '{}' --device tek4125 --width 48 --height 48 --port virtual:tek4125 --stream - -q", scene));
  CHECK(refused.exitCode == 2);
  CHECK_THAT(refused.stderrText, Catch::Contains("--stream - and --port"));
}
