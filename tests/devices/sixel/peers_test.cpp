// Every sixel golden decoded by a program no one here wrote: libsixel's
// sixel2png (Debian libsixel-bin) must give the same pixels as our
// emulator's picture of the stream. Skips with a warning where sixel2png is
// missing (scripts/setup.sh installs it).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/png.hpp"
#include "tests/devices/sixel/sixel_support.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;

namespace {

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The register count a golden was written for: 256 when its name says so.
sixel::SixelProfile profileFor(const std::filesystem::path& path) {
  sixel::SixelProfile p;
  if (path.stem().string().find("256") != std::string::npos) p.registers = 256;
  return p;
}

}  // namespace

TEST_CASE("sixel2png decodes every sixel golden to our emulator's pixels") {
  if (std::system("command -v sixel2png >/dev/null 2>&1") != 0) {
    WARN("skipped: sixel2png is not on PATH (Debian libsixel-bin; scripts/setup.sh installs it)");
    return;
  }
  testing::TempDir dir("sixel-peers");
  std::size_t compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(testing::goldenPath("sixel"))) {
    if (entry.path().extension() != ".six") continue;
    INFO(entry.path().string());
    const std::string out = dir / (entry.path().stem().string() + ".png");
    const std::string command = "sixel2png -i '" + entry.path().string() + "' -o '" + out + "'";
    REQUIRE(std::system(command.c_str()) == 0);
    const RgbImage theirs = io::readPng(out);
    sixel::SixelDecoder ours(profileFor(entry.path()));
    ours.feed(readBytes(entry.path()));
    ours.finish();
    const RgbImage mine = toRgbImage(ours.image());
    REQUIRE(theirs.width == mine.width);
    REQUIRE(theirs.height == mine.height);
    const auto diff = testing::compareImages(theirs, mine);
    CHECK(diff.differingPixels == 0);
    CHECK(diff.maxChannelDelta == 0);
    ++compared;
  }
  CHECK(compared >= 6);
}
