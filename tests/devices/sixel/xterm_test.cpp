// End to end in a real terminal: xterm (Debian's, `-ti vt340` with 256
// colour registers) under Xvfb draws sixel goldens; its window, captured
// with xwd (tests/support/xterm_capture.hpp), must match our emulator's
// picture, every pixel within 1 level. Skips with a warning where Xvfb,
// xterm or xwd is missing.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/devices/sixel/sixel_support.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/xterm_capture.hpp"

using namespace lattice;

namespace {

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("xterm -ti vt340 draws the sixel scene goldens as our emulator does") {
  for (const char* name : {"scenes/fuzzy-sphere-1000_96x96_256.six", "scenes/sphere-hole_64x64_16.six",
                           "noise-64x30-256.six"}) {
    INFO(name);
    const std::string file = testing::goldenPath("sixel/" + std::string(name)).string();
    sixel::SixelProfile profile;
    profile.registers = 256;
    sixel::SixelDecoder ours(profile);
    ours.feed(readBytes(file));
    ours.finish();
    const RgbImage mine = toRgbImage(ours.image());

    testing::XtermCaptureOptions options;
    options.xtermArguments = {"-ti", "vt340", "-xrm", "XTerm*numColorRegisters: 256", "-geometry", "40x12"};
    options.streamFile = file;
    const testing::XtermCapture capture = testing::captureXterm(options);
    if (!capture.captured()) {
      WARN("skipped: " << capture.skipReason);
      return;
    }
    REQUIRE(capture.window.width >= mine.width);
    REQUIRE(capture.window.height >= mine.height);
    RgbImage shown(mine.width, mine.height);  // the picture is at the window's top left
    for (int y = 0; y < mine.height; ++y)
      for (int x = 0; x < mine.width; ++x) std::copy_n(capture.window.pixel(x, y), 3, shown.pixel(x, y));
    const auto diff = testing::compareImages(shown, mine);
    CHECK(diff.maxChannelDelta <= 1);
  }
}
