#include <catch2/catch.hpp>

#include <climits>

#include "quantize/histogram.hpp"
#include "quantize/inverse_colormap.hpp"
#include "quantize/median_cut.hpp"
#include "tests/quantize/test_sources.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::quantize;
using lattice::testing::hash2;

namespace {

// The brute-force answer: nearest entry, lowest index on ties.
PaletteIndex bruteForceNearest(const Palette& palette, Color18 c) {
  int r = expand6to8(red6(c)), g = expand6to8(green6(c)), b = expand6to8(blue6(c));
  int best = 0, bestDistance = INT_MAX;
  for (std::size_t i = 0; i < palette.size(); ++i) {
    int d = distanceSquared(r, g, b, palette[i]);
    if (d < bestDistance) {
      bestDistance = d;
      best = static_cast<int>(i);
    }
  }
  return static_cast<PaletteIndex>(best);
}

Palette scatteredPalette(int n, int seed) {
  Palette p;
  for (int i = 0; i < n; ++i) {
    std::uint32_t h = hash2(i, seed);
    p.push_back(Rgb8{static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(h >> 8), static_cast<std::uint8_t>(h >> 16)});
  }
  return p;
}

}  // namespace

TEST_CASE("inverse colour map answers the true nearest entry for every 18-bit colour") {
  for (int n : {1, 2, 7, 64, 256}) {
    Palette palette = scatteredPalette(n, n);
    if (n == 64) palette[10] = palette[40];  // duplicates must resolve to the lower index
    InverseColorMap map(palette);
    long wrong = 0;
    for (Color18 c = 0; c < (Color18{1} << 18); ++c)
      if (map.nearest(c) != bruteForceNearest(palette, c)) ++wrong;
    INFO(n << " entries");
    CHECK(wrong == 0);
    CHECK(map.resolvedCoarseCells() == static_cast<std::size_t>(InverseColorMap::kCoarseCells));
  }
}

TEST_CASE("inverse colour map resolves only the cells it is asked about") {
  InverseColorMap map(scatteredPalette(16, 3));
  map.nearest(packColor18(0, 0, 0));
  map.nearest(packColor18(3, 3, 3));  // same 4x4x4 cell
  map.nearest(packColor18(63, 0, 0));
  CHECK(map.resolvedCoarseCells() == 2);
}

TEST_CASE("inverse colour map reuses the histogram's storage") {
  Histogram h;
  h.add(packColor18(1, 2, 3));
  Palette palette = medianCut(h, 4, {});
  std::vector<std::uint32_t> storage = h.releaseStorage();
  InverseColorMap map(palette, std::move(storage));
  CHECK(map.nearest(packColor18(1, 2, 3)) == 0);
  CHECK(map.nearest(packColor18(63, 63, 63)) == 0);
  CHECK(InverseColorMap::cacheBytes() == Histogram::kBytes);
}

TEST_CASE("inverse colour map refuses an empty palette and non-18-bit colours") {
  CHECK_THROWS_AS(InverseColorMap(Palette{}), Error);
  InverseColorMap map(Palette{Rgb8{1, 2, 3}});
  CHECK_THROWS_AS(map.nearest(Color18{1} << 18), Error);
}
