// `lattice send --port virtual:DEVICE`: the stream goes through a
// real pseudo-terminal (the serial code of a real line, XON/XOFF at the
// baud rate, the 4027's `!REP` answers) to the device's emulator, and the
// screen it draws is the one `lattice emulate` draws from the same file.
#include <catch2/catch.hpp>

#include <string>

#include <fmt/format.h>

#include "io/png.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::runLattice;

TEST_CASE("send to a virtual terminal draws the screen emulate draws", "[serial]") {
  const lattice::testing::TempDir scratch("virtual-terminal");
  const std::string scene = std::string(LATTICE_SOURCE_DIR) + "/scenes/sphere-hole.toml";
  struct Case {
    const char* device;
    const char* flags;
  };
  // The 4027 stream is long enough to be paced with `!REP 00` (strict's
  // auto pacing), so the terminal must answer every record.
  for (const Case c : {Case{"tek4125", "--baud 38400 --flow xonxoff"}, Case{"tek4027", "--flow xonxoff"},
                       Case{"tek4125", "--baud 115200 --flow none"}}) {
    const std::string stream = scratch / fmt::format("{}.stream", c.device);
    auto run = runLattice(fmt::format("render '{}' --width 96 --height 72 --device {} --stream '{}' -q", scene,
                                      c.device, stream));
    INFO(run.stderrText);
    REQUIRE(run.exitCode == 0);
    const std::string emulated = scratch / "emulated.png", sent = scratch / "sent.png";
    run = runLattice(fmt::format("emulate --device {} '{}' -o '{}'", c.device, stream, emulated));
    REQUIRE(run.exitCode == 0);
    run = runLattice(fmt::format("send '{}' --port virtual:{} {} -o '{}'", stream, c.device, c.flags, sent));
    INFO(c.device << " " << c.flags << ": " << run.stderrText);
    REQUIRE(run.exitCode == 0);
    CHECK_THAT(run.stderrText, Catch::Contains("a virtual Tektronix") && Catch::Contains("0 malformed"));
    if (std::string(c.device) == "tek4027") CHECK_THAT(run.stderrText, Catch::Contains("waiting for the"));
    const lattice::RgbImage a = lattice::io::readPng(emulated), b = lattice::io::readPng(sent);
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    CHECK(a.rgb == b.rgb);
  }
}

TEST_CASE("send -o is for a virtual terminal only", "[cli]") {
  const auto run = runLattice("send /dev/null --port /dev/ttyS99 -o x.png");
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::Contains("use --port virtual:DEVICE"));
}
