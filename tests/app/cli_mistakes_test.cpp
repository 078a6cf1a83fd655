// Command-line mistakes, run on the real binary: each gets one
// `lattice: error:` line that names the fix, and the exit code of its kind
// (docs/cli.md). The before/after messages are in docs/cli.md ("Mistakes").
#include <catch2/catch.hpp>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "app/cli/did_you_mean.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::runLattice;
using lattice::testing::TempDir;

namespace {

const std::string kScene = std::string(LATTICE_SOURCE_DIR) + "/scenes/torus-floor.toml";

// One line, in the one form.
void checkOneLine(const lattice::testing::CommandRun& run) {
  CHECK(run.stderrText.rfind("lattice: error: ", 0) == 0);
  CHECK(run.stderrText.find('\n') == run.stderrText.size() - 1);
}

}  // namespace

TEST_CASE("did you mean: the nearest known name within a third of the letters") {
  using lattice::app::nearestName;
  const std::vector<std::string> commands = {"bake", "diff", "emulate", "export", "render", "send", "table1"};
  CHECK(nearestName("rendr", commands) == "render");
  CHECK(nearestName("emualte", commands) == "emulate");  // a swap is one edit
  CHECK(nearestName("sned", commands) == "send");
  CHECK_FALSE(nearestName("xyzzy", commands).has_value());
  const std::vector<std::string> flags = {"--width", "--height", "--threads", "--colors"};
  CHECK(nearestName("--widht", flags) == "--width");
  CHECK(nearestName("--colours", flags) == "--colors");
  CHECK(nearestName("--thre", flags) == "--threads");  // the only name it begins
  CHECK(lattice::app::editDistance("kitten", "sitting") == 3);
}

TEST_CASE("a mistyped command or flag is named with the nearest known one", "[cli]") {
  auto run = runLattice("rendr scenes/x.toml");
  INFO(run.stderrText);
  CHECK(run.exitCode == 2);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("unknown command 'rendr'") && Catch::Contains("did you mean 'render'?"));

  run = runLattice(fmt::format("render {} --widht 100 -o /tmp/never.png", kScene));
  INFO(run.stderrText);
  CHECK(run.exitCode == 2);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("render: unknown flag '--widht'") &&
                                 Catch::Contains("did you mean '--width'?") &&
                                 Catch::Contains("lattice render --help"));

  run = runLattice("");
  CHECK(run.exitCode == 2);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("give a command: bake"));

  // CLI11's own errors in the same form.
  run = runLattice(fmt::format("render {} --device tek9999 -o /tmp/never.png", kScene));
  CHECK(run.exitCode == 2);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("render: --device"));
}

TEST_CASE("flags that would do nothing in the combination are refused with the reason", "[cli]") {
  const TempDir scratch("cli-combinations");
  auto run = runLattice(fmt::format("render {} --stream '{}'", kScene, scratch / "x.tek"));
  INFO(run.stderrText);
  CHECK(run.exitCode == 2);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("--stream takes a device's command stream") &&
                                 Catch::Contains("add --device (tek4125"));

  run = runLattice(fmt::format("render {} --colors 16 --dither fs -o '{}'", kScene, scratch / "x.png"));
  INFO(run.stderrText);
  CHECK(run.exitCode == 2);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("--colors sets the quantizer") && Catch::Contains("lattice quantize"));
  CHECK_FALSE(std::filesystem::exists(scratch / "x.png"));

  run = runLattice(fmt::format("render {} --device tek4125 --baud 9600 --stream '{}'", kScene, scratch / "x.tek"));
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::Contains("--baud sets the serial line of --port"));
  // ...but it is the rate a time budget counts at, for a device with no serial line of its own.
  run = runLattice(fmt::format("render {} --device sixel --width 32 --height 32 --wire-seconds 1 --baud 9600 --stream '{}'",
                               kScene, scratch / "x.six"));
  INFO(run.stderrText);
  CHECK(run.exitCode == 0);
  CHECK(std::filesystem::file_size(scratch / "x.six") <= 960);
}

TEST_CASE("outputs are checked before any work, read-only ones need --force", "[cli]") {
  const TempDir scratch("cli-outputs");
  // /proc is a directory nobody can create files in, root included.
  auto run = runLattice(fmt::format("render {} --width 8 --height 8 -o /proc/lattice-never.png", kScene));
  INFO(run.stderrText);
  CHECK(run.exitCode == 4);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("cannot write in /proc"));
  CHECK_FALSE(Catch::Contains("lattice render:").match(run.stderrText));  // nothing rendered

  const std::string locked = scratch / "locked.png";
  { std::ofstream(locked) << "keep me"; }
  ::chmod(locked.c_str(), 0444);
  run = runLattice(fmt::format("render {} --width 8 --height 8 -o '{}'", kScene, locked));
  INFO(run.stderrText);
  CHECK(run.exitCode == 4);
  checkOneLine(run);
  CHECK_THAT(run.stderrText, Catch::Contains("read-only; add --force"));
  CHECK(std::filesystem::file_size(locked) == 7);

  run = runLattice(fmt::format("render {} --width 8 --height 8 --force -o '{}'", kScene, locked));
  INFO(run.stderrText);
  CHECK(run.exitCode == 0);
  CHECK(std::filesystem::file_size(locked) > 7);
}

TEST_CASE("the render summary says 1 thread, not 1 threads", "[cli]") {
  const TempDir scratch("cli-thread");
  const auto run = runLattice(fmt::format("render {} --width 8 --height 8 --threads 1 -o '{}'", kScene, scratch / "t.png"));
  INFO(run.stderrText);
  CHECK(run.exitCode == 0);
  CHECK_THAT(run.stderrText, Catch::Contains("1 thread)"));
}

TEST_CASE("a nested command's flags are its own: export pov --width is known, --widht is not", "[cli]") {
  const TempDir dir("nested-flags");
  const auto bad = runLattice(fmt::format("export pov scenes/torus-floor.toml --width 0 -o '{}'", dir / "a.pov"));
  CHECK(bad.exitCode == 2);
  CHECK_THAT(bad.stderrText, Catch::StartsWith("lattice: error: export pov: --width: '0' is out of range") &&
                                 Catch::Contains("`lattice export pov --help`"));
  const auto typo = runLattice(fmt::format("export pov scenes/torus-floor.toml --widht 10 -o '{}'", dir / "a.pov"));
  CHECK(typo.exitCode == 2);
  CHECK_THAT(typo.stderrText, Catch::Contains("export pov: unknown flag '--widht'; did you mean '--width'?"));
}

TEST_CASE("a repeatable flag takes one value each time: --set before the stream file", "[cli]") {
  const TempDir dir("set-then-file");
  REQUIRE(runLattice(fmt::format("render scenes/sphere-hole.toml --device tek4014 --width 64 --height 64 -q --stream '{}'",
                                 dir / "h.tek"))
              .exitCode == 0);
  const auto run = runLattice(fmt::format("emulate --device tek4014 --set bits=10 --set baud=9600 '{}' -o '{}'",
                                          dir / "h.tek", dir / "h.png"));
  INFO(run.stderrText);
  CHECK(run.exitCode == 0);
  CHECK(std::filesystem::exists(dir / "h.png"));
}

TEST_CASE("a removed flag says what to write instead", "[cli]") {
  const auto run = runLattice("render scenes/torus-floor.toml --device apollo --apollo-profile dn660-4");
  CHECK(run.exitCode == 2);
  CHECK_THAT(run.stderrText, Catch::Contains("render: --apollo-profile was removed; write --set profile=P"));
}
