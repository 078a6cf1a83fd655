// `lattice bake` (app/scene_bake.hpp): the C++ the firmware compiles. The
// firmware tests (tests/firmware/) check that a baked scene renders the
// host's bytes; these check the file itself and the command's refusals,
// and run without the ARM tools.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/run_lattice.hpp"

namespace {

namespace fs = std::filesystem;
using lattice::testing::runLattice;

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t occurrences(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("bake: 1000 instances of a lattice share one table in flash, as constant data, numbers as exact hex literals") {
  const fs::path out = fs::path(LATTICE_BINARY_DIR) / "bake-test-fuzzy.cpp";
  const auto run =
      runLattice(fmt::format("bake {}/scenes/fuzzy-sphere-1000.toml --size 32x16 -o {}", LATTICE_SOURCE_DIR, out.string()));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  const std::string text = readText(out);
  CHECK(occurrences(text, "alignas(4) const std::uint8_t kFlash") == 1);
  // The scatter is one leaf over constexpr arrays: its 1000 placements and
  // their BVH (lht/leaf/baked_lattice_union.hpp), no function per instance.
  CHECK(occurrences(text, "makeBakedLatticeUnionDesc(") == 1);
  CHECK(occurrences(text, "makeBakedLatticeLeafDesc(") == 0);
  CHECK(occurrences(text, "{lattice::lht::LatticeAffine<lattice::Fixed32>(") == 1000);
  CHECK(occurrences(text, "constexpr lattice::Bvh<lattice::Fixed32>::Node kBvhNodes") == 1);
  CHECK(occurrences(text, "[[gnu::noinline]] lattice::NodeDesc node") < 10);
  CHECK(text.find("1000 instances held as constant data") != std::string::npos);
  CHECK(text.find("b.width = 32;") != std::string::npos);
  CHECK(text.find("b.height = 16;") != std::string::npos);
  CHECK(text.find("HistogramForm>(1)") != std::string::npos);  // small by default
  // The camera's eye (0, 1.6, -5) with 1.6 as its exact double.
  CHECK(text.find("s.camera.eye = lattice::Vec3d(0x0p+0, 0x1.999999999999ap+0, -0x1.4p+2);") != std::string::npos);
  fs::remove(out);
}

TEST_CASE("bake: a bad size or device setting exits 2 naming the flag, and writes nothing") {
  const fs::path out = fs::path(LATTICE_BINARY_DIR) / "bake-test-refused.cpp";
  fs::remove(out);
  const auto size = runLattice(fmt::format("bake {}/scenes/hook.toml --size 64 -o {}", LATTICE_SOURCE_DIR, out.string()));
  CHECK(size.exitCode == 2);
  CHECK(size.stderrText.find("--size 64") != std::string::npos);
  const auto set =
      runLattice(fmt::format("bake {}/scenes/hook.toml --set planes=99 -o {}", LATTICE_SOURCE_DIR, out.string()));
  CHECK(set.exitCode == 2);
  CHECK(!fs::exists(out));
  const auto help = runLattice("bake --help");
  CHECK(help.exitCode == 0);
}
