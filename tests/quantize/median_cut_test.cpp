#include <catch2/catch.hpp>

#include <algorithm>
#include <climits>
#include <set>
#include <tuple>

#include "quantize/median_cut.hpp"
#include "tests/quantize/test_sources.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::quantize;
using lattice::testing::photoLike;

namespace {

Histogram photoHistogram(int width, int height) {
  Histogram h;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) h.add(photoLike(x, y, width, height));
  return h;
}

Rgb8 rgbOf(Color18 c) { return Rgb8{expand6to8(red6(c)), expand6to8(green6(c)), expand6to8(blue6(c))}; }

// Sum over pixels of the squared distance to the nearest entry (brute force).
double totalError(const Histogram& h, const Palette& palette) {
  double sum = 0;
  for (Color18 c = 0; c < Histogram::kCells; ++c) {
    if (h.count(c) == 0) continue;
    Rgb8 v = rgbOf(c);
    int best = INT_MAX;
    for (Rgb8 p : palette) best = std::min(best, distanceSquared(v.r, v.g, v.b, p));
    sum += double(h.count(c)) * best;
  }
  return sum;
}

bool sameColors(const Palette& a, const Palette& b) {
  auto key = [](Rgb8 c) { return std::make_tuple(c.r, c.g, c.b); };
  std::set<std::tuple<int, int, int>> sa, sb;
  for (Rgb8 c : a) sa.insert(key(c));
  for (Rgb8 c : b) sb.insert(key(c));
  return sa == sb;
}

}  // namespace

TEST_CASE("median cut never gives more than K entries") {
  Histogram h = photoHistogram(96, 64);
  REQUIRE(h.distinctColors() > 256);
  for (int k : {1, 2, 3, 8, 16, 255, 256})
    for (SplitRule rule : {SplitRule::Median, SplitRule::Variance}) {
      QuantizeOptions options;
      options.split = rule;
      options.refineIterations = k == 16 ? 3 : 0;
      Palette p = medianCut(h, k, options);
      INFO("K = " << k);
      CHECK(p.size() == static_cast<std::size_t>(k));  // plenty of colours: exactly K
    }
}

TEST_CASE("one colour gives exactly that colour") {
  Histogram h;
  for (int i = 0; i < 100; ++i) h.add(packColor18(10, 20, 30));
  Palette p = medianCut(h, 256, {});
  REQUIRE(p.size() == 1);
  CHECK(p[0] == rgbOf(packColor18(10, 20, 30)));
}

TEST_CASE("two colours give both colours, or their weighted mean for K = 1") {
  Histogram h;
  for (int i = 0; i < 3; ++i) h.add(packColor18(0, 0, 0));
  h.add(packColor18(63, 0, 0));
  Palette two = medianCut(h, 2, {});
  CHECK(sameColors(two, {Rgb8{0, 0, 0}, Rgb8{255, 0, 0}}));
  Palette one = medianCut(h, 1, {});
  REQUIRE(one.size() == 1);
  CHECK(one[0] == Rgb8{64, 0, 0});  // (3 * 0 + 255) / 4 = 63.75, rounded
}

TEST_CASE("K above the number of colours yields each colour once") {
  Histogram h;
  std::vector<Color18> colors{packColor18(1, 1, 1), packColor18(1, 1, 2), packColor18(40, 3, 9),
                              packColor18(63, 63, 0), packColor18(0, 63, 63)};
  for (std::size_t i = 0; i < colors.size(); ++i)
    for (std::size_t n = 0; n <= i * 7; ++n) h.add(colors[i]);
  for (SplitRule rule : {SplitRule::Median, SplitRule::Variance}) {
    QuantizeOptions options;
    options.split = rule;
    Palette p = medianCut(h, 200, options);
    REQUIRE(p.size() == colors.size());
    Palette expected;
    for (Color18 c : colors) expected.push_back(rgbOf(c));
    CHECK(sameColors(p, expected));
  }
}

TEST_CASE("median and variance rules cut a skewed box in different places") {
  // 100 pixels at red 0, 100 at red 10, one at red 63.
  Histogram h;
  for (int i = 0; i < 100; ++i) {
    h.add(packColor18(0, 0, 0));
    h.add(packColor18(10, 0, 0));
  }
  h.add(packColor18(63, 0, 0));
  QuantizeOptions median, variance;
  variance.split = SplitRule::Variance;
  // Median: half the pixels lie at or below red 10, so the cut is after 10:
  // {0, 10} and {63}. Variance: {0} and {10, 63} leave less squared error.
  CHECK(sameColors(medianCut(h, 2, median), {Rgb8{20, 0, 0}, Rgb8{255, 0, 0}}));
  CHECK(sameColors(medianCut(h, 2, variance), {Rgb8{0, 0, 0}, Rgb8{42, 0, 0}}));
}

TEST_CASE("k-means refinement does not make the palette worse") {
  Histogram h = photoHistogram(80, 60);
  for (int k : {8, 16}) {
    Palette plain = medianCut(h, k, {});
    QuantizeOptions refined;
    refined.refineIterations = 5;
    Palette better = medianCut(h, k, refined);
    INFO("K = " << k);
    CHECK(better.size() == plain.size());
    // Rounding centroids to 8 bits may cost a hair; Lloyd steps otherwise only reduce error.
    CHECK(totalError(h, better) <= totalError(h, plain) * 1.001);
  }
}

TEST_CASE("median cut is deterministic") {
  Histogram h = photoHistogram(64, 64);
  QuantizeOptions options;
  options.refineIterations = 2;
  CHECK(medianCut(h, 16, options) == medianCut(h, 16, options));
}

TEST_CASE("median cut refuses bad K and refine counts, and gives nothing for nothing") {
  Histogram h;
  h.add(1);
  CHECK_THROWS_AS(medianCut(h, 0, {}), Error);
  CHECK_THROWS_AS(medianCut(h, 257, {}), Error);
  QuantizeOptions bad;
  bad.refineIterations = -1;
  CHECK_THROWS_AS(medianCut(h, 4, bad), Error);
  Histogram empty;
  CHECK(medianCut(empty, 16, {}).empty());
}
