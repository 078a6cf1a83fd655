// The emulators' shared drawing surface: Tek orientation, clipping, fill rule,
// and lines that are exactly the Bresenham walk.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

#include "devices/canvas.hpp"

using namespace lattice;
using namespace lattice::devices;

namespace {
long count(const IndexedImage& s, int index) {
  long n = 0;
  for (PaletteIndex p : s.pixels) n += p == index;
  return n;
}
}  // namespace

TEST_CASE("pixel y = 0 is the bottom row of the framebuffer") {
  IndexedImage s(8, 4, 2);
  *pixelAt(s, 2, 0) = 1;
  CHECK(s.at(2, 3) == 1);
  CHECK(pixelAt(s, 8, 0) == nullptr);
  CHECK(pixelAt(s, 0, -1) == nullptr);
  CHECK(pixelAt(s, 0, 4) == nullptr);
}

TEST_CASE("lines draw both ends and clip without touching memory off the screen") {
  IndexedImage s(10, 10, 4);
  drawLine(s, 0, 0, 9, 9, 1);
  CHECK(count(s, 1) == 10);
  drawLine(s, -100, 5, 100, 5, 2);  // crosses the screen
  CHECK(count(s, 2) == 10);
  drawLine(s, -50, -50, -10, 200, 3);  // entirely off the screen
  CHECK(count(s, 3) == 0);
  drawLine(s, 4, 4, 4, 4, 3);  // a single point
  CHECK(count(s, 3) == 1);
}

TEST_CASE("polygons fill pixels whose centres are inside, even-odd, clipped") {
  IndexedImage s(20, 20, 4);
  const double square[] = {2, 2, 6, 2, 6, 6, 2, 6};  // covers centres 2.5..5.5: 4 x 4
  fillPolygon(s, square, 1);
  CHECK(count(s, 1) == 16);
  const double big[] = {-5, -5, 30, -5, 30, 30, -5, 30};
  fillPolygon(s, big, 2);
  CHECK(count(s, 2) == 400);
  // A bow tie: its edges cross at the centre, leaving a left and a right
  // triangle, both filled; above and below the crossing is outside.
  IndexedImage b(20, 20, 4);
  const double bowTie[] = {0, 0, 20, 20, 20, 0, 0, 20};
  fillPolygon(b, bowTie, 1);
  CHECK(count(b, 1) == Approx(200).margin(20));
  CHECK(b.at(2, 10) == 1);   // left triangle
  CHECK(b.at(17, 10) == 1);  // right triangle
  CHECK(b.at(10, 2) == 0);   // above the crossing (Tek y = 17)
  CHECK(b.at(10, 17) == 0);  // below it (Tek y = 2)
  const double line[] = {0, 0, 10, 10};  // fewer than three points: nothing
  fillPolygon(b, line, 3);
  CHECK(count(b, 3) == 0);
}

namespace {
// The integer Bresenham walk the Tek 4125 emulator drew lines with before the
// emulators shared one canvas: the reference the clipped DDA must reproduce.
std::vector<std::pair<long, long>> bresenham(long x0, long y0, long x1, long y1) {
  std::vector<std::pair<long, long>> points;
  const long dx = std::labs(x1 - x0), dy = -std::labs(y1 - y0);
  const long sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  long err = dx + dy;
  for (;;) {
    points.emplace_back(x0, y0);
    if (x0 == x1 && y0 == y1) break;
    const long e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
  return points;
}
}  // namespace

TEST_CASE("a line is exactly the Bresenham walk, ties included, on and off the screen") {
  // Endpoints around a small screen so that lines start, end and pass
  // outside it: the clipped pixels must be exactly the walk's visible ones.
  long lines = 0, mismatches = 0;
  for (long x0 = -4; x0 <= 10; x0 += 2)
    for (long y0 = -3; y0 <= 9; y0 += 3)
      for (long x1 = -5; x1 <= 11; ++x1)
        for (long y1 = -4; y1 <= 10; ++y1) {
          IndexedImage drawn(7, 6, 2), expected(7, 6, 2);
          drawLine(drawn, x0, y0, x1, y1, 1);
          for (auto [x, y] : bresenham(x0, y0, x1, y1))
            if (PaletteIndex* p = pixelAt(expected, x, y)) *p = 1;
          ++lines;
          mismatches += drawn.pixels != expected.pixels;
        }
  INFO(lines << " lines compared");
  CHECK(lines == 8 * 5 * 17 * 15);
  CHECK(mismatches == 0);
}

TEST_CASE("a line far longer than the screen costs only its visible steps and draws them") {
  IndexedImage s(16, 16, 2);
  drawLine(s, -2000000000L, 8, 2000000000L, 8, 1);  // 4e9 steps, 16 on the screen
  CHECK(count(s, 1) == 16);
}

namespace {
// The even-odd fill as it was first written (sort each row's crossings, fill
// between pairs): fillPolygon's sweep must give the same pixels.
void referenceFill(IndexedImage& screen, const std::vector<double>& xy, PaletteIndex index) {
  const std::size_t n = xy.size() / 2;
  for (int row = 0; row < screen.height; ++row) {
    const double yc = row + 0.5;
    std::vector<double> crossings;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
      if ((yi > yc) != (yj > yc)) crossings.push_back(xj + (yc - yj) * (xi - xj) / (yi - yj));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      const int from = std::max(0, static_cast<int>(std::ceil(crossings[k] - 0.5)));
      const int to = std::min(screen.width - 1, static_cast<int>(std::floor(crossings[k + 1] - 0.5)));
      for (int x = from; x <= to; ++x) *pixelAt(screen, x, row) = index;
    }
  }
}
}  // namespace

TEST_CASE("the sweep fill gives the same pixels as sorting the crossings") {
  // Random polygons on a half-pixel grid (so crossings land exactly on pixel
  // centres and edges), many self-intersecting, some reaching off the screen.
  std::uint32_t state = 12345;
  auto next = [&](int range) {
    state = state * 1664525u + 1013904223u;
    return static_cast<int>((state >> 8) % static_cast<std::uint32_t>(range));
  };
  for (int trial = 0; trial < 400; ++trial) {
    const int points = 3 + next(12);
    std::vector<double> xy;
    for (int p = 0; p < 2 * points; ++p) xy.push_back((next(60) - 10) * 0.5 + (trial % 3 == 0 ? 0.25 : 0.0));
    IndexedImage fast(24, 20, 4), slow(24, 20, 4);
    fillPolygon(fast, xy, 1);
    referenceFill(slow, xy, 1);
    REQUIRE(fast.pixels == slow.pixels);
  }
}

TEST_CASE("lineWork counts the steps drawLine visits") {
  IndexedImage s(40, 30, 4);
  CHECK(lineWork(s, 0, 0, 39, 0) == 40);
  CHECK(lineWork(s, 5, 5, 5, 5) == 1);
  CHECK(lineWork(s, -100, -100, -50, -60) == 0);
  // A vector 130,000 pixels long costs the screen's width and two steps each side
  // (the widening that keeps rounding from losing a visible point).
  CHECK(lineWork(s, -65000, 10, 65000, 10) <= 44);
}
