// `lattice emulate` checks what it was given: a PNG, a scene or an
// empty file is refused with exit 3 naming what it is; another device's
// stream names the device to use; --raw decodes the bytes anyway.
#include <catch2/catch.hpp>
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
const std::string kGolden = LATTICE_GOLDEN_DIR;
const std::string kSource = LATTICE_SOURCE_DIR;
}  // namespace

TEST_CASE("emulate refuses what is not the device's stream, saying what it is", "[cli]") {
  const lattice::testing::TempDir scratch("emulate-recognise");
  const std::string out = scratch / "screen.png";
  const std::string empty = scratch / "empty.tek";
  { std::ofstream touch(empty); }
  struct Case {
    std::string file;
    std::string device;
    std::string says;
  };
  const Case cases[] = {
      {kGolden + "/tek4027/rings-48x32-screen.png", "tek4125", "this is a PNG image, not a Tektronix 4125 stream"},
      {kSource + "/scenes/torus-floor.toml", "tek4125", "this is a scene file (TOML)"},
      {empty, "tek4027", "this is an empty file"},
      {kGolden + "/tek4027/rings-48x32.tek", "tek4125", "emulate it with --device tek4027"},
      {kGolden + "/tek4125/scene24x16_4planes.tek", "tek4027", "emulate it with --device tek4125"},
      {kGolden + "/tek4125/scene24x16_4planes.tek", "apollo", "not a"},
      // The 4125 reads a 4014 stream too, but the advice is the narrower device.
      {kGolden + "/tek4014/rings-96x64.tek", "tek4027",
       "this is a Tektronix 4014 stream, not a Tektronix 4027 stream; emulate it with --device tek4014"},
  };
  for (const Case& c : cases) {
    const auto run = runLattice(fmt::format("emulate --device {} '{}' -o '{}'", c.device, c.file, out));
    INFO(c.file << " as " << c.device << ": " << run.stderrText);
    CHECK(run.exitCode == 3);
    CHECK_THAT(run.stderrText, Catch::StartsWith("lattice: error: ") && Catch::Contains(c.says) &&
                                   Catch::Contains("--raw"));
    CHECK_FALSE(std::filesystem::exists(out));
  }
  // The streams themselves pass, from a file and from standard input.
  for (const char* device : {"tek4125", "tek4027"}) {
    const std::string stream = std::string(device) == "tek4125" ? kGolden + "/tek4125/scene24x16_4planes.tek"
                                                                : kGolden + "/tek4027/rings-48x32.tek";
    auto run = runLattice(fmt::format("emulate --device {} '{}' -o '{}'", device, stream, out));
    INFO(run.stderrText);
    CHECK(run.exitCode == 0);
    // Standard input (runLattice gives /dev/null): the check holds the head back, then decodes it.
    const int status = std::system(fmt::format("'{}' emulate --device {} - -o '{}' < '{}'",
                                               lattice::testing::latticeBinary().string(), device, out, stream)
                                       .c_str());
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  }
  // --raw: the old behaviour, a picture of whatever the bytes say.
  const auto raw = runLattice(fmt::format("emulate --device tek4125 --raw '{}' -o '{}'",
                                          kGolden + "/tek4027/rings-48x32-screen.png", out));
  INFO(raw.stderrText);
  CHECK(raw.exitCode == 0);
  CHECK(std::filesystem::exists(out));
}
