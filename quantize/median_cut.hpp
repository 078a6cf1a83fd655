#pragma once
// Heckbert's median cut (SIGGRAPH 1982, "Color Image Quantization for Frame
// Buffer Display"), over the 18-bit histogram:
//   1. one box holds every colour; shrink it to fit the colours inside;
//   2. pick the box to split (most pixels for the median rule, largest summed
//      squared error for the variance rule); a box of one colour cannot split
//      and gives its turn to the next;
//   3. cut it across its longest dimension at the median by pixel count (or
//      at the variance-minimising point), shrink both halves, repeat to K boxes;
//   4. each box's colour is the population-weighted mean of its cells.
// Optional k-means refinement then moves each entry to the mean of the cells
// nearest to it (Lloyd iterations; Heckbert 1982 sec. 4 calls this iterative
// improvement).
#include "foundation/scanline.hpp"
#include "quantize/histogram.hpp"
#include "quantize/quantize_options.hpp"

namespace lattice::quantize {

// At most maxColors entries (fewer when the histogram has fewer distinct
// colours); an empty histogram gives an empty palette. maxColors must be
// 1..256, refineIterations 0..100: otherwise lattice::Error(Usage).
Palette medianCut(const Histogram& histogram, int maxColors, const QuantizeOptions& options);

// Squared Euclidean distance in 8-bit RGB: the metric the palette and the
// inverse map both use, so "nearest" means the same thing everywhere.
constexpr int distanceSquared(int r, int g, int b, Rgb8 c) {
  int dr = r - c.r, dg = g - c.g, db = b - c.b;
  return dr * dr + dg * dg + db * db;
}

// The nearest entry of a non-empty palette to (r, g, b), the lowest index on
// ties: by a scan (the inverse map's uncached form and the refinement).
inline std::size_t nearestEntry(int r, int g, int b, const Palette& palette) {
  std::size_t best = 0;
  int bestDistance = distanceSquared(r, g, b, palette[0]);
  for (std::size_t i = 1; i < palette.size() && bestDistance > 0; ++i) {
    const int d = distanceSquared(r, g, b, palette[i]);
    if (d < bestDistance) {  // strict: the lowest index keeps a tie
      bestDistance = d;
      best = i;
    }
  }
  return best;
}

// Moves each palette entry to the weighted mean of the histogram cells whose
// nearest entry it is, `iterations` times (or until nothing moves).
void refinePalette(const Histogram& histogram, Palette& palette, int iterations);

}  // namespace lattice::quantize
