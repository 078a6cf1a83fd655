#include <catch2/catch.hpp>

#include <vector>

#include "quantize/inverse_colormap.hpp"
#include "quantize/row_mapper.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::quantize;

namespace {

// Maps a flat picture of one colour onto a black/white palette and returns the
// fraction of white pixels.
double whiteFraction(Dither dither, Color18 grey, int width, int height, std::vector<PaletteIndex>* all = nullptr) {
  InverseColorMap map(Palette{Rgb8{0, 0, 0}, Rgb8{255, 255, 255}});
  RowMapper mapper(map, width, dither);
  std::vector<Color18> in(static_cast<std::size_t>(width), grey);
  std::vector<PaletteIndex> out(static_cast<std::size_t>(width));
  long white = 0;
  for (int y = 0; y < height; ++y) {
    mapper.mapRow(y, in, out);
    for (PaletteIndex i : out) white += i;
    if (all) all->insert(all->end(), out.begin(), out.end());
  }
  return double(white) / (double(width) * height);
}

}  // namespace

TEST_CASE("without dithering a flat grey maps to one entry") {
  CHECK(whiteFraction(Dither::None, packColor18(20, 20, 20), 37, 11) == 0.0);
  CHECK(whiteFraction(Dither::None, packColor18(40, 40, 40), 37, 11) == 1.0);
}

TEST_CASE("Floyd-Steinberg keeps the mean of a flat grey") {
  // Grey 16/63 is 65/255: about a quarter white.
  double expected = double(expand6to8(16)) / 255.0;
  double fraction = whiteFraction(Dither::FloydSteinberg, packColor18(16, 16, 16), 101, 57);
  CHECK(fraction == Approx(expected).margin(0.01));
  double half = whiteFraction(Dither::FloydSteinberg, packColor18(32, 32, 32), 100, 64);
  CHECK(half == Approx(double(expand6to8(32)) / 255.0).margin(0.01));
}

TEST_CASE("Floyd-Steinberg works on a one-pixel-wide column and is deterministic") {
  double fraction = whiteFraction(Dither::FloydSteinberg, packColor18(32, 32, 32), 1, 200);
  CHECK(fraction == Approx(double(expand6to8(32)) / 255.0).margin(0.02));
  std::vector<PaletteIndex> a, b;
  whiteFraction(Dither::FloydSteinberg, packColor18(21, 21, 21), 33, 20, &a);
  whiteFraction(Dither::FloydSteinberg, packColor18(21, 21, 21), 33, 20, &b);
  CHECK(a == b);
}

TEST_CASE("Bayer dithering mixes two entries in an 8x8-periodic pattern") {
  std::vector<PaletteIndex> all;
  const int width = 32, height = 16;
  double fraction = whiteFraction(Dither::Bayer, packColor18(32, 32, 32), width, height, &all);
  CHECK(fraction > 0.3);
  CHECK(fraction < 0.7);
  for (int y = 0; y + 8 < height; ++y)
    for (int x = 0; x + 8 < width; ++x) {
      auto at = [&](int px, int py) { return all[static_cast<std::size_t>(py * width + px)]; };
      REQUIRE(at(x, y) == at(x + 8, y));
      REQUIRE(at(x, y) == at(x, y + 8));
    }
}

TEST_CASE("row mapper refuses rows of the wrong size") {
  InverseColorMap map(Palette{Rgb8{0, 0, 0}});
  RowMapper mapper(map, 4, Dither::FloydSteinberg);
  std::vector<Color18> in(3);
  std::vector<PaletteIndex> out(3);
  CHECK_THROWS_AS(mapper.mapRow(0, in, out), Error);
  CHECK(RowMapper::errorRowBytes(4) == 6 * 3 * sizeof(int));
}
