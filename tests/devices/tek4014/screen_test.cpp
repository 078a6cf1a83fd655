// The 4014's bit screen (Tek4014Screen) against the plain definition of a
// line, stepped one point at a time here, and against devices::drawLine
// (canvas.hpp), which the other emulators draw with: random vectors near,
// across, along the edges of and far off the screen, on small odd screens
// and on the 4014's two, must light the same pixels, and each vector is
// charged exactly the pixels it lights. Then the decoder as a whole against
// a screen drawn with devices::drawLine, read part-way through the stream too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "devices/canvas.hpp"
#include "devices/tek4014/tek4014_decoder.hpp"
#include "devices/tek4014/tek4014_driver.hpp"
#include "devices/tek4014/tek4014_screen.hpp"

using namespace lattice;
using namespace lattice::tek4014;

namespace {

struct Line {
  long x0, y0, x1, y1;
};

// Point i of n = max(|dx|, |dy|) at start + i * delta / n, rounded to
// nearest with ties away from the start, i = 0..n; those on a w x h screen
// are lit in `screen` when it is given (y = 0 the bottom row). Returns how
// many were on it.
std::uint64_t referenceLine(const Line& l, int w, int h, IndexedImage* screen = nullptr) {
  const long dx = l.x1 - l.x0, dy = l.y1 - l.y0;
  const long n = std::max(std::labs(dx), std::labs(dy));
  auto along = [n](long origin, long delta, long i) {
    if (n == 0) return origin;
    const long m = (2 * i * std::labs(delta) + n) / (2 * n);
    return delta < 0 ? origin - m : origin + m;
  };
  std::uint64_t on = 0;
  for (long i = 0; i <= n; ++i) {
    const long x = along(l.x0, dx, i), y = along(l.y0, dy, i);
    if (x < 0 || y < 0 || x >= w || y >= h) continue;
    if (screen != nullptr) screen->at(static_cast<int>(x), static_cast<int>(h - 1 - y)) = 1;
    ++on;
  }
  return on;
}

std::uint64_t referenceLine(IndexedImage& screen, const Line& l) {
  return referenceLine(l, screen.width, screen.height, &screen);
}

IndexedImage blank(int w, int h) { return IndexedImage(w, h, 2); }

// Pixels where two screens differ: a count, so that a failure prints a
// number rather than two screens.
long differing(const IndexedImage& a, const IndexedImage& b) {
  if (a.width != b.width || a.height != b.height) return -1;
  long n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
  return n;
}

IndexedImage painted(const Tek4014Screen& s) {
  IndexedImage out = blank(s.width(), s.height());
  s.paint(out);
  return out;
}

// Random vectors of every kind for a w x h screen: `far` is how far off the
// screen an end may lie.
std::vector<Line> randomLines(std::mt19937& rng, int w, int h, long far, int count) {
  auto pick = [&rng](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  std::vector<Line> lines;
  for (int k = 0; k < count; ++k) {
    const long X = pick(-far, w + far), Y = pick(-far, h + far);
    switch (k % 8) {
      case 0: lines.push_back({pick(0, w - 1), pick(0, h - 1), pick(0, w - 1), pick(0, h - 1)}); break;  // inside
      case 1: lines.push_back({X, Y, pick(-far, w + far), pick(-far, h + far)}); break;  // anywhere
      case 2: lines.push_back({X, Y, X + pick(-3, 3), pick(-far, h + far)}); break;      // nearly vertical
      case 3: lines.push_back({X, Y, pick(-far, w + far), Y + pick(-3, 3)}); break;      // nearly horizontal
      case 4: {  // 45 degrees, and just off it
        const long d = pick(-far - w, far + w);
        lines.push_back({X, Y, X + d, Y + (k % 16 < 8 ? d : -d) + pick(-1, 1)});
        break;
      }
      case 5: {  // along an edge, or just outside it
        const long e = pick(0, 3);
        if (k % 16 < 8) {
          const long x = std::vector<long>{-1, 0, w - 1, w}[static_cast<std::size_t>(e)];
          lines.push_back({x, Y, x + pick(-1, 1), pick(-far, h + far)});
        } else {
          const long y = std::vector<long>{-1, 0, h - 1, h}[static_cast<std::size_t>(e)];
          lines.push_back({X, y, pick(-far, w + far), y + pick(-1, 1)});
        }
        break;
      }
      case 6: lines.push_back({X, Y, X, Y}); break;  // a dot, on or off the screen
      default: {  // exact ties: one coordinate changes by an even n, the other by an odd number
        // (n / 2 when that is odd, else above n / 2: mostly diagonal steps)
        const long m = pick(1, 20), n = 2 * m, odd = m % 2 ? m : m + 1 + 2 * pick(0, (m - 2) / 2);
        const long a = pick(0, 1) ? n : -n, b = pick(0, 1) ? odd : -odd;
        lines.push_back(k % 16 < 8 ? Line{X, Y, X + a, Y + b} : Line{X, Y, X + b, Y + a});
        break;
      }
    }
  }
  return lines;
}

void checkLines(int w, int h, long far, int count, unsigned seed) {
  std::mt19937 rng(seed);
  Tek4014Screen screen(w, h);
  IndexedImage all = blank(w, h);
  const auto lines = randomLines(rng, w, h, far, count);
  for (const Line& l : lines) {
    INFO(w << "x" << h << " screen, vector " << l.x0 << "," << l.y0 << " -> " << l.x1 << "," << l.y1);
    IndexedImage expected = blank(w, h), old = blank(w, h);
    const std::uint64_t on = referenceLine(expected, l);
    devices::drawLine(old, l.x0, l.y0, l.x1, l.y1, 1);
    REQUIRE(differing(old, expected) == 0);  // the reference is the shared canvas's line
    screen.clear();
    const Tek4014Screen::Vector v = screen.vector(l.x0, l.y0, l.x1, l.y1);
    screen.draw(v);
    CHECK(differing(painted(screen), expected) == 0);
    CHECK(v.work() == (l.x0 == l.x1 && l.y0 == l.y1 ? 1 : on));
    CHECK(v.work() <= devices::lineWork(old, l.x0, l.y0, l.x1, l.y1));  // never more than the canvas charges
    referenceLine(all, l);
  }
  // All of them on one screen: the four bitmaps together.
  screen.clear();
  for (const Line& l : lines) screen.draw(screen.vector(l.x0, l.y0, l.x1, l.y1));
  CHECK(differing(painted(screen), all) == 0);
}

// A 12-bit address, all five bytes.
std::string at12(int x, int y) {
  return {char(0x20 | (y >> 7)), char(0x60 | (y & 3) << 2 | (x & 3)), char(0x60 | ((y >> 2) & 31)),
          char(0x20 | (x >> 7)), char(0x40 | ((x >> 2) & 31))};
}

}  // namespace

TEST_CASE("4014 screen: vectors on small screens light the reference pixels and are charged them") {
  checkLines(37, 23, 60, 2000, 1);
  checkLines(64, 64, 200, 2000, 2);
  checkLines(65, 129, 1000, 2000, 3);
  checkLines(200, 9, 5, 2000, 4);
}

TEST_CASE("4014 screen: vectors far off the screen, on the 10-bit screen") {
  checkLines(1024, 780, 300, 160, 5);
  checkLines(1024, 780, 150000, 80, 6);
}

TEST_CASE("4014 screen: vectors on the 12-bit screen") {
  checkLines(4096, 3120, 2000, 48, 7);
  checkLines(4096, 3120, 140000, 16, 8);
}

TEST_CASE("4014 screen: an erase darkens every bitmap, drawing goes on after it") {
  Tek4014Screen screen(70, 50);
  IndexedImage expected = blank(70, 50);
  // One vector for each bitmap: diagonal, column, row, antidiagonal.
  const std::vector<Line> lines = {{0, 0, 69, 49}, {10, -5, 12, 60}, {-3, 20, 90, 21}, {69, 0, 20, 45}};
  for (const Line& l : lines) {
    screen.draw(screen.vector(l.x0, l.y0, l.x1, l.y1));
    referenceLine(expected, l);
  }
  CHECK(differing(painted(screen), expected) == 0);
  screen.clear();
  const IndexedImage dark = painted(screen);
  CHECK(std::count(dark.pixels.begin(), dark.pixels.end(), PaletteIndex{1}) == 0);
  screen.draw(screen.vector(5, 5, 5, 40));
  IndexedImage again = blank(70, 50);
  referenceLine(again, {5, 5, 5, 40});
  CHECK(differing(painted(screen), again) == 0);
}

TEST_CASE("4014 emulator: random 10- and 12-bit streams draw what devices::drawLine draws") {
  std::mt19937 rng(4014);
  auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  for (const int bits : {10, 12}) {
    Tek4014Profile profile;
    profile.addressBits = bits;
    const int s = profile.shift();
    Tek4014Decoder decoder(profile);
    IndexedImage expected = blank(profile.width(), profile.height());
    std::uint64_t work = 0;
    int beamX = 0, beamY = 0;
    auto vector = [&](int x, int y) {
      const Line l{beamX >> s, beamY >> s, x >> s, y >> s};
      devices::drawLine(expected, l.x0, l.y0, l.x1, l.y1, 1);
      work += l.x0 == l.x1 && l.y0 == l.y1 ? 1 : referenceLine(l, profile.width(), profile.height());
      beamX = x;
      beamY = y;
    };
    for (int round = 0; round < 40; ++round) {
      std::string stream;
      switch (round % 5) {
        case 0:
        case 1: {  // a polyline
          const int x = pick(0, 4095), y = pick(0, 4095);
          stream += "\x1d" + at12(x, y);
          beamX = x;
          beamY = y;
          for (int k = pick(1, 30); k > 0; --k) {
            const int nx = pick(0, 4095), ny = pick(0, 4095);
            stream += at12(nx, ny);
            vector(nx, ny);
          }
          break;
        }
        case 2: {  // point plots
          stream += "\x1c";
          for (int k = pick(1, 30); k > 0; --k) {
            const int x = pick(0, 4095), y = pick(0, 4095);
            stream += at12(x, y);
            beamX = x;
            beamY = y;
            vector(x, y);
          }
          break;
        }
        case 3: {  // incremental steps off the screen's left or bottom edge, then GS BEL back across it
          const int steps = pick(1000, 12000);
          const char step = pick(0, 1) ? 'B' : 'H';  // west or south
          stream += "\x1e" "P" + std::string(static_cast<std::size_t>(steps), step);
          for (int k = 0; k < steps; ++k) vector(beamX - (step == 'B'), beamY - (step == 'H'));
          const int x = pick(0, 4095), y = pick(0, 4095);
          stream += "\x1d\x07" + at12(x, y);
          vector(x, y);
          break;
        }
        default:  // a page erase
          stream += "\x1b\x0c";
          std::fill(expected.pixels.begin(), expected.pixels.end(), PaletteIndex{0});
          work += static_cast<std::uint64_t>(profile.width()) * static_cast<std::uint64_t>(profile.height());
          beamX = 0;
          beamY = kHomeY;
          break;
      }
      decoder.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(stream.data()), stream.size()));
      INFO(bits << "-bit, after round " << round);
      REQUIRE(decoder.beamX() == beamX);
      REQUIRE(decoder.beamY() == beamY);
      CHECK(decoder.report().pixelWork == work);
      if (round % 4 == 3) CHECK(differing(decoder.image(), expected) == 0);  // read part-way
    }
    decoder.finish();
    CHECK(differing(decoder.image(), expected) == 0);
    CHECK(decoder.report().malformed == 0);
  }
}
