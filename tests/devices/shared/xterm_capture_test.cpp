// The xterm harness (tests/support/xterm_capture.hpp) against a stream whose
// picture is known by construction: a sixel image of two registers, a red
// 12x6 band over a band half blue, half hole. Skips with the reason where
// Xvfb, xterm or xwd is missing.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "foundation/error.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xterm_capture.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

// Pixel (x, y) of the capture as r, g, b.
std::array<int, 3> at(const RgbImage& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

}  // namespace

TEST_CASE("xwd decoding rejects what is not a ZPixmap dump") {
  CHECK_THROWS_AS(decodeXwd(std::vector<std::uint8_t>(40, 0)), Error);
  CHECK_THROWS_AS(decodeXwd(std::vector<std::uint8_t>(200, 0)), Error);
}

TEST_CASE("xterm -ti vt340 shows a sixel stream and the harness captures it") {
  TempDir dir("xterm-harness");
  const std::string stream = dir / "bands.six";
  {
    std::ofstream out(stream, std::ios::binary);
    // Register 1 red (RGB percent), register 2 blue; band 1 all red, band 2
    // blue in columns 0..5 only.
    out << "\033Pq\"1;1;12;12#1;2;100;0;0#2;2;0;0;100#1!12~-#2!6~\033\\";
  }
  XtermCaptureOptions options;
  options.xtermArguments = {"-ti", "vt340", "-geometry", "40x10"};
  options.streamFile = stream;
  const XtermCapture capture = captureXterm(options);
  if (!capture.captured()) {
    WARN("skipped: " << capture.skipReason);
    return;
  }
  REQUIRE(capture.window.width >= 12);
  REQUIRE(capture.window.height >= 12);
  CHECK(at(capture.window, 0, 0) == std::array<int, 3>{255, 0, 0});
  CHECK(at(capture.window, 11, 5) == std::array<int, 3>{255, 0, 0});
  CHECK(at(capture.window, 0, 6) == std::array<int, 3>{0, 0, 255});
  CHECK(at(capture.window, 5, 11) == std::array<int, 3>{0, 0, 255});
  // Outside the picture: the terminal's own background, not a register.
  CHECK(at(capture.window, 30, 30) != std::array<int, 3>{255, 0, 0});
  CHECK(at(capture.window, 30, 30) != std::array<int, 3>{0, 0, 255});
}
