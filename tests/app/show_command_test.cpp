// `lattice show` end to end with the real binary: a recorded Tek 4027 golden
// and a sixel golden are re-encoded as sixel that our emulator decodes
// cleanly to the right size; a file that is neither PNG nor a known stream
// exits 2 naming --as; a decoded stream sent by its indices (no RGB picture
// between) writes the very bytes its picture as a PNG does.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

#include "devices/sixel/sixel_decoder.hpp"
#include "io/png.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

IndexedImage decodeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  sixel::SixelProfile profile;
  profile.registers = 256;
  sixel::SixelDecoder d(profile);
  d.feed(bytes);
  d.finish();
  CHECK(d.report().malformed == 0);
  CHECK(d.report().unknownCommands == 0);
  return d.image();
}

}  // namespace

TEST_CASE("lattice show re-encodes recorded streams as sixel") {
  TempDir dir("show");
  const std::string tek = goldenPath("tek4027/rings-48x32.tek").string();
  REQUIRE(runLattice("show " + tek + " --stream " + (dir / "rings.six")).exitCode == 0);
  const IndexedImage rings = decodeFile(dir / "rings.six");
  CHECK(rings.width == 640);  // the 4027's whole 640x350 screen
  CHECK(rings.height == 350);

  const std::string six = goldenPath("sixel/scenes/torus-floor_80x60_256.six").string();
  REQUIRE(runLattice("show " + six + " --set registers=256 --stream " + (dir / "again.six")).exitCode == 0);
  const IndexedImage again = decodeFile(dir / "again.six");
  CHECK(again.width == 80);
  CHECK(again.height == 60);
  // The same picture, exactly: its 256 colours or fewer are sent as they are (no median cut),
  // and a register's percent goes back to the same percent.
  CHECK(compareImages(toRgbImage(again), toRgbImage(decodeFile(six))).maxChannelDelta == 0);

  const CommandRun bad = runLattice("show " + sourcePath("README.md").string() + " --stream " + (dir / "x.six"));
  CHECK(bad.exitCode == 2);
  CHECK(bad.stderrText.find("--as") != std::string::npos);
}

TEST_CASE("lattice show of a sixel stream: its indices, not an RGB round trip, and the same bytes") {
  // The stream path (quantize::exactPalette of the decoded indices) against
  // the PNG path (exactPalette of the RGB picture) on the same picture: the
  // same palette order and indices, so byte for byte the same stream. Both
  // colour counts: a golden of 16 registers and one of 256.
  TempDir dir("show-direct");
  for (const auto& [golden, registers] : {std::pair{"sixel/scenes/sphere-hole_64x64_16.six", 16},
                                          std::pair{"sixel/scenes/fuzzy-sphere-1000_96x96_256.six", 256}}) {
    INFO(golden);
    const std::string six = goldenPath(golden).string();
    const std::string png = dir / "picture.png";
    io::writePng(png, toRgbImage(decodeFile(six)));
    const std::string set = " --set registers=" + std::to_string(registers) + " --stream ";
    REQUIRE(runLattice("show " + six + set + (dir / "from-stream.six")).exitCode == 0);
    REQUIRE(runLattice("show " + png + set + (dir / "from-png.six")).exitCode == 0);
    const std::vector<std::uint8_t> fromStream = readFile(dir / "from-stream.six");
    CHECK(fromStream.size() > 100);
    CHECK(fromStream == readFile(dir / "from-png.six"));
    // A stream lattice show wrote ranks its registers already: shown again, it is itself.
    REQUIRE(runLattice("show " + (dir / "from-stream.six") + set + (dir / "again.six")).exitCode == 0);
    CHECK(readFile(dir / "again.six") == fromStream);
  }
}
