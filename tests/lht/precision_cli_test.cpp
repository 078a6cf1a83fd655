// The entry-precision and form knobs from the command line, run through the
// real `lattice` binary (test_lht depends on it): `rasterize --precision` and
// `--form`, `render --lht-precision` and `--lht-form` overriding the scene,
// `lht-info` reporting them, and `render --lht-stats`.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lht/file/lht_file.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;
using namespace lattice::lht;
using lattice::testing::runLattice;

using lattice::testing::TempDir;

namespace {

// A tiny scene whose lattice is cached next to it.
std::string ballScene(const std::string& extraLatticeKeys = "") {
  return R"(
[options]
width = 8
height = 8
[camera]
type = "look_at"
eye = [0.0, 0.0, -4.0]
target = [0.0, 0.0, 0.0]
fov = 40
[[lights]]
position = [2.0, 3.0, -4.0]
intensity = 20.0
[[lattices]]
name = "ball"
spacing = 1.0
oversample = 2
cache = "ball.lht"
)" + extraLatticeKeys + R"(
object = { type = "sphere", radius = 0.5 }
[[objects]]
type = "lattice"
lattice = "ball"
)";
}


std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("precision CLI: rasterize --precision writes that form and lht-info reports it") {
  INFO("lattice is not built (" << lattice::testing::latticeBinary() << "): build the `lattice` target or set LATTICE_EXE");
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("precision-cli");
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    const std::string lht = dir / fmt::format("{}.lht", form.name);
    const auto run = runLattice(fmt::format("rasterize --shape sphere --oversample 2 --precision {} -o '{}' --stats >'{}'",
                                            form.name, lht, dir / "stats.txt"));
    INFO(run.stderrText);
    REQUIRE(run.exitCode == 0);
    CHECK(readText(dir / "stats.txt").find(fmt::format("precision={}", form.name)) != std::string::npos);
    const LhtFile read = readLhtFile(lht);
    CHECK(read.precision() == form.precision);
    CHECK(read.hashed().entryCount() == 1562);  // the sphere at f_lat 2, whatever the precision
    REQUIRE(runLattice(fmt::format("lht-info '{}' >'{}'", lht, dir / "info.txt")).exitCode == 0);
    const std::string info = readText(dir / "info.txt");
    CHECK(info.find(fmt::format("precision:     {} ({}-byte entries", form.name, form.entryBytes)) !=
          std::string::npos);
    CHECK(info.find(fmt::format("{} bytes per slot", form.entryBytes - 4)) != std::string::npos);  // no chain index
    CHECK(info.find("format:        version 4") != std::string::npos);
    CHECK(info.find("layout:        open addressing, linear probing, 2232 slots") != std::string::npos);
  }
  const auto bad = runLattice(fmt::format("rasterize --shape sphere --precision huge -o '{}'", dir / "x.lht"));
  CHECK(bad.exitCode == 2);
  CHECK(bad.stderrText.find("--precision: unknown entry precision 'huge'") != std::string::npos);
  CHECK(bad.stderrText.find("thesis (14 B/entry), wide (16 B/entry), compact (13 B/entry)") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "x.lht"));
}

TEST_CASE("precision CLI: rasterize --scene takes the scene's precision unless --precision overrides it") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("precision-cli");
  std::ofstream(dir / "s.toml") << ballScene("precision = \"compact\"");
  REQUIRE(runLattice(fmt::format("rasterize --scene '{}' --name ball -o '{}'", dir / "s.toml", dir / "a.lht"))
              .exitCode == 0);
  CHECK(readLhtFile(dir / "a.lht").precision() == LhtPrecision::Compact);
  REQUIRE(runLattice(fmt::format("rasterize --scene '{}' --name ball --precision wide -o '{}'", dir / "s.toml",
                                 dir / "b.lht"))
              .exitCode == 0);
  CHECK(readLhtFile(dir / "b.lht").precision() == LhtPrecision::Wide);
}

TEST_CASE("precision CLI: render --lht-precision overrides the scene and a cache of another precision is refused") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("precision-cli");
  std::ofstream(dir / "s.toml") << ballScene();
  const auto wide = runLattice(fmt::format("render '{}' --lht-precision wide -o '{}'", dir / "s.toml", dir / "w.png"));
  INFO(wide.stderrText);
  REQUIRE(wide.exitCode == 0);
  CHECK(readLhtFile(dir / "ball.lht").precision() == LhtPrecision::Wide);  // rasterized at the override
  // The scene asks for the thesis's entry: the wide cache must be refused, naming both.
  const auto stale = runLattice(fmt::format("render '{}' -o '{}'", dir / "s.toml", dir / "t.png"));
  CHECK(stale.exitCode == 3);
  CHECK(stale.stderrText.find("ball.lht") != std::string::npos);
  CHECK(stale.stderrText.find("'wide' entries (16 bytes each) but 'thesis' entries were asked for") !=
        std::string::npos);
  CHECK(runLattice(fmt::format("render '{}' --lht-precision wide -o '{}'", dir / "s.toml", dir / "w2.png")).exitCode ==
        0);
  const auto bad = runLattice(fmt::format("render '{}' --lht-precision 16 -o '{}'", dir / "s.toml", dir / "x.png"));
  CHECK(bad.exitCode == 2);
  // The flag's names are the table settings' (loader/table_settings.hpp), `scene` the lattice's own.
  CHECK(bad.stderrText.find("--lht-precision: 16 not in {thesis,wide,compact,scene}") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST_CASE("precision CLI: a bad precision in a scene names the file and line and column and the valid values") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("precision-cli");
  std::ofstream(dir / "s.toml") << ballScene("precision = \"double\"");
  const auto run = runLattice(fmt::format("render '{}' -o '{}'", dir / "s.toml", dir / "x.png"));
  CHECK(run.exitCode == 3);
  CHECK(run.stderrText.find(dir / "s.toml:18:13:") != std::string::npos);
  CHECK(run.stderrText.find("unknown LHT entry `precision` 'double'") != std::string::npos);
  CHECK(run.stderrText.find("thesis (14 B/entry), wide (16 B/entry), compact (13 B/entry)") != std::string::npos);
}

TEST_CASE("form CLI: rasterize --form compressed writes version 3, lht-info shows the form, render uses it") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("form-cli");
  const std::string lht = dir / "c.lht";
  const auto run = runLattice(fmt::format("rasterize --shape sphere --oversample 2 --form compressed -o '{}' --stats >'{}'",
                                          lht, dir / "stats.txt"));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  CHECK(readText(dir / "stats.txt").find("form=compressed") != std::string::npos);
  const LhtFile read = readLhtFile(lht);
  CHECK(read.form() == LhtForm::Compressed);
  CHECK(read.entryCount() == 1562);
  REQUIRE(runLattice(fmt::format("lht-info '{}' >'{}'", lht, dir / "info.txt")).exitCode == 0);
  const std::string info = readText(dir / "info.txt");
  CHECK(info.find("format:        version 3") != std::string::npos);
  CHECK(info.find("form:          compressed") != std::string::npos);
  CHECK(info.find("pair space:    98 boundary points, 9506 ordered pairs") != std::string::npos);
  CHECK(info.find("pair layout:   symmetric") != std::string::npos);
  // The scene's cache in each form; the pictures are the same bytes.
  std::ofstream(dir / "s.toml") << ballScene();
  REQUIRE(runLattice(fmt::format("render '{}' --lht-form compressed -o '{}'", dir / "s.toml", dir / "c.png")).exitCode == 0);
  CHECK(readLhtFile(dir / "ball.lht").form() == LhtForm::Compressed);
  std::filesystem::remove(dir / "ball.lht");
  REQUIRE(runLattice(fmt::format("render '{}' -o '{}'", dir / "s.toml", dir / "h.png")).exitCode == 0);
  CHECK(readLhtFile(dir / "ball.lht").form() == LhtForm::Hashed);
  CHECK(readText(dir / "c.png") == readText(dir / "h.png"));
  const auto bad = runLattice(fmt::format("render '{}' --lht-form zip -o '{}'", dir / "s.toml", dir / "x.png"));
  CHECK(bad.exitCode == 2);
  CHECK(bad.stderrText.find("--lht-form: zip not in {hashed,compressed,on-demand,scene}") != std::string::npos);
}

TEST_CASE("form CLI: render --lht-stats prints each lattice's look-ups, without it nothing is counted") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("stats-cli");
  std::ofstream(dir / "s.toml") << ballScene();
  const auto counted = runLattice(fmt::format("render '{}' --lht-stats -o '{}'", dir / "s.toml", dir / "a.png"));
  REQUIRE(counted.exitCode == 0);
  INFO(counted.stderrText);
  CHECK(counted.stderrText.find("lht-stats: lattice 'ball' (f_lat 2): ") != std::string::npos);
  CHECK(counted.stderrText.find("distinct (p_i, p_o) asked: ") != std::string::npos);
  CHECK(counted.stderrText.find("of N_iz = 3486 counted as eq. 1.3 does") != std::string::npos);
  const auto plain = runLattice(fmt::format("render '{}' -o '{}'", dir / "s.toml", dir / "b.png"));
  REQUIRE(plain.exitCode == 0);
  CHECK(plain.stderrText.find("lht-stats") == std::string::npos);
  CHECK(readText(dir / "a.png") == readText(dir / "b.png"));
  const auto full = runLattice(fmt::format("render '{}' --full --lht-stats -o '{}'", dir / "s.toml", dir / "f.png"));
  CHECK(full.stderrText.find("lht-stats: no lattice was looked up") != std::string::npos);
}

TEST_CASE("precision CLI: render --lattice-lookup and the scene's `lookup` pick the look-up, bad names are refused") {
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const TempDir dir("lookup-cli");
  std::ofstream(dir / "s.toml") << ballScene();
  std::ofstream(dir / "b.toml") << ballScene("lookup = \"blend\"\n");
  struct Case {
    const char* scene;
    const char* args;
    const char* png;
  };
  for (const Case& c : {Case{"s.toml", "--lattice-lookup thesis", "t.png"}, Case{"s.toml", "--lattice-lookup blend", "b.png"},
                        Case{"b.toml", "", "key.png"}, Case{"b.toml", "--lattice-lookup thesis", "over.png"},
                        Case{"s.toml", "", "default.png"}}) {
    const auto run = runLattice(fmt::format("render '{}' {} -o '{}'", dir / c.scene, c.args, dir / c.png));
    INFO(c.scene << " " << c.args << ": " << run.stderrText);
    REQUIRE(run.exitCode == 0);
  }
  const auto bytes = [&](const char* png) { return readText(dir / png); };
  CHECK(bytes("t.png") != bytes("b.png"));       // the option reaches the leaves
  CHECK(bytes("key.png") == bytes("b.png"));     // the scene key does the same
  CHECK(bytes("over.png") == bytes("t.png"));    // the option overrides the key
  CHECK(bytes("default.png") == bytes("t.png"));  // thesis is the default
  const auto bad = runLattice(fmt::format("render '{}' --lattice-lookup nearest -o '{}'", dir / "s.toml", dir / "x.png"));
  CHECK(bad.exitCode != 0);
  CHECK(bad.stderrText.find("--lattice-lookup: nearest not in {thesis,blend,scene}") != std::string::npos);
  std::ofstream(dir / "bad.toml") << ballScene("lookup = \"nearest\"\n");
  const auto badKey = runLattice(fmt::format("render '{}' -o '{}'", dir / "bad.toml", dir / "x.png"));
  CHECK(badKey.exitCode != 0);
  CHECK(badKey.stderrText.find("bad.toml") != std::string::npos);
  CHECK(badKey.stderrText.find("unknown lattice `lookup` 'nearest'; use one of thesis, blend") != std::string::npos);
}
