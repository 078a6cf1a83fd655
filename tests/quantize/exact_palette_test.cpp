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

TEST_CASE("exact palette of an indexed picture: what the RGB path gives, without it") {
  // A decoded stream's shape: 256 registers, a few used, two of them the
  // same colour, one unused register equal to a used one, ties in count.
  IndexedImage image(7, 3, 256);
  for (std::size_t k = 0; k < 256; ++k)
    image.colormap[k] = Rgb8{static_cast<std::uint8_t>(k), static_cast<std::uint8_t>(255 - k), 9};
  image.colormap[40] = image.colormap[7];  // 7 and 40: one colour
  image.colormap[41] = image.colormap[3];  // unused, equal to a used register
  const PaletteIndex rows[3][7] = {{3, 3, 7, 9, 9, 40, 200}, {3, 7, 7, 9, 200, 200, 5}, {40, 3, 3, 9, 5, 5, 200}};
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 7; ++x) image.at(x, y) = rows[y][x];
  const auto direct = quantize::exactPalette(image, 16);
  const auto viaRgb = quantize::exactPalette(toRgbImage(image), 16);
  REQUIRE(direct.has_value());
  REQUIRE(viaRgb.has_value());
  CHECK(direct->colormap == viaRgb->colormap);
  CHECK(direct->pixels == viaRgb->pixels);
  CHECK(direct->colormap.size() == 5);                  // 3, 7 (= 40), 9, 200, 5
  CHECK(direct->colormap[0] == image.colormap[3]);      // 5 pixels, met first
  CHECK(direct->colormap[1] == image.colormap[7]);      // 5 too: 3 of register 7 and 2 of 40
  CHECK(direct->colormap[2] == image.colormap[9]);      // 4, met before 200's 4
  CHECK(toRgbImage(*direct).rgb == toRgbImage(image).rgb);
  CHECK_FALSE(quantize::exactPalette(image, 4).has_value());  // five colours
  CHECK(quantize::exactPalette(image, 5).has_value());
  image.colormap.resize(200);  // index 200 is past the colour map now: left to the RGB path
  CHECK_FALSE(quantize::exactPalette(image, 256).has_value());
}
