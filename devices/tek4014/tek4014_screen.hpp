#pragma once
// The 4014 emulator's screen: dots lit or dark, kept as bits while a stream
// is decoded and turned into an IndexedImage (0 dark, 1 lit) when the
// picture is asked for. Pixel y = 0 is the bottom row, as the terminal counts.
//
// Method and tunables:
//  - Vectors light exactly the pixels devices::drawLine (canvas.hpp) lights:
//    point i of n = max(|dx|, |dy|) at start + i * delta / n, rounded to
//    nearest with ties away from the start, both ends drawn, clipped to the
//    screen. Each step moves one pixel along the major axis (the one that
//    changes by n) and, at the steps the rounding carries, one along the
//    other too: a straight step or a diagonal one.
//  - So a vector is a list of runs: straight steps in a row (or a column),
//    joined by single diagonal steps; or, when more than half the steps are
//    diagonal, diagonal steps in a row joined by single straight ones. Four
//    bitmaps of the screen hold them, OR-ed when the picture is read: rows
//    (a row's bits along x), columns (a column's bits along y), diagonals
//    (y - x constant) and antidiagonals (x + y constant), the last two with
//    their bits along x. A run sets consecutive bits of one line, 64 to a
//    word: a vertical vector 3,120 dots long is 49 word writes, a 45-degree
//    one as many. A byte a pixel, a steep vector wrote one byte a row apart
//    each step, and at 4096x3120 (12.7 MB) every step missed the cache.
//  - The runs of a vector near 45 degrees are one or two dots, so the
//    bitmaps keep the lines in groups of eight, word k of each side by side
//    (a cache line): neighbouring lines share it.
//  - Clipping is exact: the visible points are one range of steps, found
//    with a few divisions before anything is drawn; Vector::work() is its
//    length, the work a vector is charged (devices/work_budget.hpp). A
//    zero-length vector (a dot) is charged 1 even off the screen.
//  - Coordinates are pixels and may lie far off the screen: products are
//    formed in 128 bits where they can be large.
#include <cstdint>
#include <vector>

#include "foundation/indexed_image.hpp"

namespace lattice::tek4014 {

class Tek4014Screen {
 public:
  // One vector's visible points: steps first..last of 0..steps.
  struct Vector {
    long x0 = 0, y0 = 0;  // the start
    bool xMajor = true;   // x changes by `steps`, y by minorDelta (or the other way)
    int majorSign = 1;    // +1 or -1 a step along the major axis
    int minorSign = 1;    // +1 or -1 a carry along the other
    long steps = 0;       // n
    long minorDelta = 0;  // carries, at most n
    long first = 0;       // the visible steps (none when last < first)
    long last = -1;
    // The pixels the vector lights on the screen (1 for a dot anywhere).
    std::uint64_t work() const;
  };

  Tek4014Screen(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // The vector from (x0, y0) to (x1, y1), clipped; nothing is drawn yet.
  Vector vector(long x0, long y0, long x1, long y1) const;
  void draw(const Vector& v);
  void clear();
  // Writes the screen into `image` (width x height; every pixel set).
  void paint(IndexedImage& image) const;

  // Bytes the bitmaps take for a width x height screen.
  static std::uint64_t bitmapBytes(int width, int height);

 private:
  // Lines of bits in groups of eight (word k of a group's lines side by
  // side). A Lines is where a bitmap's words are, copied into a drawing loop
  // by value so that the compiler need not reload it after every store.
  struct Lines {
    std::uint64_t* words;
    long stride;  // words a line
    static long index(long line, long k, long stride) { return ((line >> 3) * stride + k) * 8 + (line & 7); }
    // Bits from..to of a line, both in range; inline, as most runs of a
    // vector near 45 degrees (or near the bitmap's own direction) are short.
    void set(long line, long from, long to) const {
      std::uint64_t* w = words + index(line, 0, stride);
      const long a = from >> 6, z = to >> 6;
      const std::uint64_t head = ~std::uint64_t{0} << (from & 63);
      const std::uint64_t tail = ~std::uint64_t{0} >> (63 - (to & 63));
      if (a == z) {
        w[8 * a] |= head & tail;
        return;
      }
      w[8 * a] |= head;
      for (long k = a + 1; k < z; ++k) w[8 * k] = ~std::uint64_t{0};
      w[8 * z] |= tail;
    }
  };

  struct Bitmap {
    long lines, length;  // lines of `length` bits
    long stride;         // words a line
    std::vector<std::uint64_t> words;
    Bitmap(long lineCount, long bitCount);
    Lines view() { return {words.data(), stride}; }
    std::uint64_t word(long line, long k) const { return words[static_cast<std::size_t>(Lines::index(line, k, stride))]; }
    // Calls lit(line, bit) for every set bit.
    template <class Lit>
    void forEachSet(Lit lit) const;
  };

  // Where a vector's runs go: run after run along `lines`, the first on
  // `line` from bit `position`; between two runs the line changes by
  // lineStep and the position by `gap` past the last run's end.
  struct Run {
    Lines lines{};
    long line = 0, lineStep = 0, position = 0, gap = 0;
  };
  // The runs of steps first..last (forEachRun in the .cpp), each `Along`
  // (+1 or -1) a step along its line.
  template <int Along>
  static void drawRuns(Run r, long n, long d, long tie, long count, long first, long last);

  int width_, height_;
  Bitmap rows_;           // height lines of width bits (x)
  Bitmap columns_;        // width lines of height bits (y)
  Bitmap diagonals_;      // line y - x + width - 1, bits x
  Bitmap antidiagonals_;  // line x + y, bits x
};

}  // namespace lattice::tek4014
