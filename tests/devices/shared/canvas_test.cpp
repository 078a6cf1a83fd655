// The emulators' shared drawing surface: Tek orientation, clipping, fill rule,
// and lines that are exactly the Bresenham walk.
#include <catch2/catch.hpp>

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
