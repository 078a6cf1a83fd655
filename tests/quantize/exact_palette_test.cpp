// quantize/exact_palette.hpp: a picture of few enough colours is indexed by
// its own colours, exactly, the most used first; one colour too many and it
// is left to the median cut.
#include <catch2/catch.hpp>

#include "quantize/exact_palette.hpp"

using namespace lattice;

namespace {

void set(RgbImage& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* p = image.pixel(x, y);
  p[0] = r, p[1] = g, p[2] = b;
}

}  // namespace

TEST_CASE("exact palette: own colours, most used first, every pixel as it was") {
  RgbImage image(5, 2);  // black, but for 3 red and 2 grey-blue pixels
  set(image, 0, 0, 200, 10, 10);
  set(image, 2, 0, 200, 10, 10);
  set(image, 4, 1, 200, 10, 10);
  set(image, 1, 1, 17, 18, 250);
  set(image, 3, 1, 17, 18, 250);
  const auto exact = quantize::exactPalette(image, 3);
  REQUIRE(exact.has_value());
  REQUIRE(exact->colormap.size() == 3);
  CHECK(exact->colormap[0] == Rgb8{0, 0, 0});      // 5 pixels
  CHECK(exact->colormap[1] == Rgb8{200, 10, 10});  // 3
  CHECK(exact->colormap[2] == Rgb8{17, 18, 250});  // 2
  CHECK(toRgbImage(*exact).rgb == image.rgb);
  CHECK_FALSE(quantize::exactPalette(image, 2).has_value());  // one colour too many
}

TEST_CASE("exact palette: 256 colours fit 256 registers, 257 do not") {
  RgbImage image(257, 3);
  for (int x = 0; x < 257; ++x)
    for (int y = 0; y < 3; ++y)
      set(image, x, y, static_cast<std::uint8_t>(x % 256), 7, 9);  // column 256 repeats column 0
  const auto all = quantize::exactPalette(image, 256);
  REQUIRE(all.has_value());
  CHECK(all->colormap.size() == 256);
  CHECK(toRgbImage(*all).rgb == image.rgb);
  set(image, 5, 1, 255, 255, 255);  // a 257th colour
  CHECK_FALSE(quantize::exactPalette(image, 256).has_value());
  CHECK_FALSE(quantize::exactPalette(RgbImage(), 16).has_value());  // nothing to index
}
