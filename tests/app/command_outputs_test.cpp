// A command's outputs are one transaction (foundation/system/output_transaction.hpp):
// the stream, the PNG and the --at snapshots land together when the command
// succeeds, and on any error none is left and old files are untouched. The
// snapshots take -o's checks (read-only files, --force), and --at takes at
// most kMaxStreamPoints items. Run through the real binary, as a user would.
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::runLattice;

namespace {

// Full-screen 4125 rectangle fills (ESC R R, two 12-bit corners, a fill
// index): each one charges the emulator's drawing budget a whole screen, so
// enough of them are refused with exit 3 after the first screens are drawn.
std::string rectangleFills(int count) {
  const auto xy = [](int x, int y) {
    std::string b;
    b += char(0x20 | y >> 7);
    b += char(0x60 | (y & 3) << 2 | (x & 3));
    b += char(0x60 | ((y >> 2) & 31));
    b += char(0x20 | x >> 7);
    b += char(0x40 | ((x >> 2) & 31));
    return b;
  };
  const std::string one = "\x1bRR" + xy(0, 0) + xy(4095, 4095) + char(0x20 | 1 | 0x10);
  std::string all;
  for (int i = 0; i < count; ++i) all += one;
  return all;
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::size_t filesIn(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

std::string source(const char* relative) { return fmt::format("{}/{}", LATTICE_SOURCE_DIR, relative); }

}  // namespace

TEST_CASE("emulate --at on a stream the drawing budget refuses leaves no snapshot", "[output][at]") {
  const lattice::testing::TempDir dir("at-budget");
  write(dir / "fills.tek", rectangleFills(2000));
  const auto run = runLattice(fmt::format("emulate --device tek4125 '{}' -o '{}' --at 1%,50%", dir / "fills.tek",
                                          dir / "o.png"));
  INFO(run.stderrText);
  CHECK(run.exitCode == 3);
  CHECK_THAT(run.stderrText, Catch::Contains("budget"));
  CHECK(filesIn(dir.path()) == 1);  // the stream alone: no o.png, no o-at1pct.png, no temporaries
}

TEST_CASE("emulate --at: a file-size limit on the second snapshot leaves none of them", "[output][at]") {
  const lattice::testing::TempDir dir("at-full");
  REQUIRE(runLattice(fmt::format("render '{}' --device tek4125 --width 256 --height 256 -q --stream '{}'",
                                 source("scenes/torus-floor.toml"), dir / "t.tek"))
              .exitCode == 0);
  // A PNG of the 4125's screen that has drawn nothing compresses to a few
  // KB, the whole picture to more: bash's `ulimit -f` (1 KiB blocks) fails
  // the later write with EFBIG, as a full disk fails it with ENOSPC. SIGXFSZ
  // is ignored so the write returns the error instead of killing the process.
  const std::string command = fmt::format(
      "trap '' XFSZ; ulimit -f 8; exec '{}' emulate --device tek4125 '{}' -o '{}' --at 0%,100% 2>'{}'",
      lattice::testing::latticeBinary().string(), dir / "t.tek", dir / "o.png", dir / "err.txt");
  const int status = std::system(fmt::format("bash -c \"{}\"", command).c_str());
  REQUIRE(WIFEXITED(status));
  std::ifstream err(dir / "err.txt");
  const std::string message((std::istreambuf_iterator<char>(err)), {});
  INFO(message);
  CHECK(WEXITSTATUS(status) == 4);
  CHECK_FALSE(std::filesystem::exists(dir / "o-at0pct.png"));
  CHECK_FALSE(std::filesystem::exists(dir / "o-at100pct.png"));
  CHECK_FALSE(std::filesystem::exists(dir / "o.png"));
  CHECK(filesIn(dir.path()) == 2);  // t.tek and err.txt: no temporaries
}

TEST_CASE("render: a PNG that cannot be written takes the stream with it", "[output]") {
  // The PNG goes to a 4 KiB file system that fills, the stream beside it to
  // one that does not: a private mount namespace (unshare -m, as root) so the
  // tmpfs is nobody else's and vanishes with the process.
  const lattice::testing::TempDir dir("render-pair");
  write(dir / "x.tek", "the user's old stream");
  std::filesystem::create_directory(dir / "full");
  const std::string command = fmt::format(
      "mount -t tmpfs -o size=4k tmpfs '{}' 2>/dev/null || exit 90; exec '{}' render '{}' --device tek4125 "
      "--width 64 --height 64 -q --stream '{}' -o '{}' 2>'{}'",
      dir / "full", lattice::testing::latticeBinary().string(), source("scenes/torus-floor.toml"), dir / "x.tek",
      dir / "full/s.png", dir / "err.txt");
  const int status = std::system(fmt::format("unshare -m sh -c \"{}\" 2>/dev/null", command).c_str());
  REQUIRE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 90 || (WEXITSTATUS(status) == 1 && !std::filesystem::exists(dir / "err.txt"))) {
    WARN("skipped: needs `unshare -m` and `mount -t tmpfs` (root in a namespace-capable sandbox) to fill a disk");
    return;
  }
  std::ifstream err(dir / "err.txt");
  const std::string message((std::istreambuf_iterator<char>(err)), {});
  INFO(message);
  CHECK(WEXITSTATUS(status) == 4);
  CHECK_THAT(message, Catch::Contains("not written, as the command failed: " + (dir / "x.tek")));
  std::ifstream old(dir / "x.tek");
  CHECK(std::string((std::istreambuf_iterator<char>(old)), {}) == "the user's old stream");
  CHECK(filesIn(dir.path()) == 3);  // x.tek, err.txt and full/: no new stream, no temporaries
}

TEST_CASE("emulate --at: a read-only snapshot is refused without --force and replaced with it", "[output][at]") {
  const lattice::testing::TempDir dir("at-readonly");
  REQUIRE(runLattice(fmt::format("render '{}' --device tek4125 --width 32 --height 32 -q --stream '{}'",
                                 source("scenes/torus-floor.toml"), dir / "t.tek"))
              .exitCode == 0);
  write(dir / "o-at50pct.png", "keep me");
  ::chmod((dir / "o-at50pct.png").c_str(), 0444);
  const std::string args = fmt::format("emulate --device tek4125 '{}' -o '{}' --at 50%", dir / "t.tek", dir / "o.png");
  const auto refused = runLattice(args);
  INFO(refused.stderrText);
  CHECK(refused.exitCode == 4);
  CHECK_THAT(refused.stderrText, Catch::Contains("o-at50pct.png") && Catch::Contains("--force"));
  CHECK_FALSE(std::filesystem::exists(dir / "o.png"));
  std::ifstream kept(dir / "o-at50pct.png");
  CHECK(std::string((std::istreambuf_iterator<char>(kept)), {}) == "keep me");
  CHECK(runLattice(args + " --force").exitCode == 0);
  CHECK(std::filesystem::file_size(dir / "o-at50pct.png") > 100);
}

TEST_CASE("emulate --at refuses NaN, infinities, huge offsets and more than 32 points before reading", "[output][at]") {
  const lattice::testing::TempDir dir("at-numbers");
  write(dir / "t.tek", rectangleFills(1));
  for (const char* at : {"nan%", "inf", "1e300", "-1", "101%", "1.5", "%", "1%,,2%"}) {
    const auto run =
        runLattice(fmt::format("emulate --device tek4125 '{}' -o '{}' --at '{}'", dir / "t.tek", dir / "o.png", at));
    INFO(at << ": " << run.stderrText);
    CHECK(run.exitCode == 2);
    CHECK_THAT(run.stderrText, Catch::StartsWith("lattice: error: --at"));
  }
  std::string many;
  for (int i = 0; i < 33; ++i) many += fmt::format("{}{}", i ? "," : "", i);
  const auto run = runLattice(fmt::format("emulate --device tek4125 '{}' -o '{}' --at {}", dir / "t.tek", dir / "o.png", many));
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::Contains("more than 32 points"));
  CHECK(filesIn(dir.path()) == 1);
}
