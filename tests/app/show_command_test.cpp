// `lattice show` end to end with the real binary: a recorded Tek 4027 golden
// and a sixel golden are re-encoded as sixel that our emulator decodes
// cleanly to the right size; a file that is neither PNG nor a known stream
// (text, a scene, noise) is refused with exit 3 saying what it is; a Tek 4014
// stream is told from a 4125 one by its bytes; a decoded stream sent by its
// indices (no RGB picture between) writes the very bytes its picture as a
// PNG does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

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

}

TEST_CASE("lattice show refuses what is neither a PNG nor a stream, saying what it is", "[show]") {
  TempDir dir("show-refuse");
  const std::string out = dir / "x.six";
  const std::string noise = dir / "noise.bin";
  {
    std::mt19937 rng(2024);
    std::ofstream file(noise, std::ios::binary);
    for (int i = 0; i < 65536; ++i) file.put(static_cast<char>(rng() >> 24));
  }
  struct Case {
    std::string args;
    int exitCode;
    std::string says;
  };
  const Case cases[] = {
      {sourcePath("README.md").string(), 3, "this is text, not a stream of any device"},
      {sourcePath("scenes/sphere-hole.toml").string(), 3, "this is a scene file (TOML)"},
      {noise, 3, "this is binary data, not a stream of any device"},
      // Named as a device's stream, it must look like one: a PNG is shown as a PNG.
      {goldenPath("tek4027/rings-48x32-screen.png").string() + " --as tek4125", 3, "show it without --as"},
      {goldenPath("tek4027/rings-48x32.tek").string() + " --as tek4125", 3, "show it with --as tek4027"},
      {sourcePath("README.md").string() + " --raw", 2, "--raw requires --as"},
  };
  for (const Case& c : cases) {
    const CommandRun run = runLattice("show " + c.args + " --stream " + out);
    INFO(c.args << ": " << run.stderrText);
    CHECK(run.exitCode == c.exitCode);
    CHECK(run.stderrText.find(c.says) != std::string::npos);
    if (c.exitCode == 3) CHECK(run.stderrText.find("--raw") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  // --as with --raw decodes whatever the bytes say, as before the check.
  const CommandRun raw = runLattice("show " + noise + " --as tek4125 --raw --stream " + out);
  INFO(raw.stderrText);
  CHECK(raw.exitCode == 0);
  CHECK(std::filesystem::exists(out));
}

TEST_CASE("lattice show tells a Tek 4014 stream by its bytes and draws it as the 4014 does", "[show]") {
  // The README's stream: ESC FF, then GS/FS graphics, which the 4125 reads
  // too; decoded as a 4125 stream it was a black screen. Shown without
  // --as, it must be the very picture `emulate --device tek4014` draws.
  TempDir dir("show-4014");
  const std::string hole = dir / "hole.tek";
  CommandRun run = runLattice("render " + sourcePath("scenes/sphere-hole.toml").string() +
                              " --device tek4014 --height 776 -q --stream " + hole);
  REQUIRE(run.exitCode == 0);
  run = runLattice("show " + hole + " --stream " + (dir / "shown.six"));
  INFO(run.stderrText);
  REQUIRE(run.exitCode == 0);
  CHECK(run.stderrText.find("(tek4014 stream, 1024x780") != std::string::npos);
  REQUIRE(runLattice("emulate --device tek4014 " + hole + " -o " + (dir / "screen.png")).exitCode == 0);
  REQUIRE(runLattice("show " + (dir / "screen.png") + " --stream " + (dir / "screen.six")).exitCode == 0);
  CHECK(readFile(dir / "shown.six") == readFile(dir / "screen.six"));
  // Not a blank screen: some pixels differ from the first one.
  const IndexedImage shown = decodeFile(dir / "shown.six");
  REQUIRE_FALSE(shown.pixels.empty());
  const auto likeFirst = std::count(shown.pixels.begin(), shown.pixels.end(), shown.pixels.front());
  CHECK(static_cast<std::size_t>(likeFirst) < shown.pixels.size());
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
