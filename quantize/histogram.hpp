#pragma once
// The colour histogram of an 18-bit image: one counter per Color18, 2^18 cells.
//
// Counter width: 32 bits, saturating at 2^32-1. A 1024x1024 frame has 2^20
// pixels, and even a 65536x65536 one (2^32) only saturates a single cell of a
// one-colour image, so saturation is a guard, never a working regime. The cost
// is 2^18 * 4 B = 1 MiB; 16-bit counters (libjpeg halves all cells on overflow)
// would save 512 KiB but lose population accuracy on large flat areas, which
// is exactly what a rendered lattice scene has (backgrounds, shaded faces).
// After the palette is built the same 1 MiB is handed to the inverse colour
// map as its cache (releaseStorage), so a run never holds both.
#include <cstdint>
#include <span>
#include <vector>

#include "foundation/scanline.hpp"

namespace lattice::quantize {

class Histogram {
 public:
  static constexpr std::size_t kCells = std::size_t{1} << 18;
  static constexpr std::size_t kBytes = kCells * sizeof(std::uint32_t);

  Histogram();

  void add(Color18 color);
  // Adds every pixel of a row; a colour outside 0..2^18-1 is a caller bug
  // (RowSource18 contract) and throws lattice::Error(Internal).
  void addRow(std::span<const Color18> row);
  // Adds every step-th pixel of the row, starting at column 0.
  void addRowSampled(std::span<const Color18> row, int step);

  std::uint32_t count(Color18 color) const { return counts_[color]; }
  std::uint64_t totalPixels() const { return total_; }
  std::size_t distinctColors() const;
  std::span<const std::uint32_t> cells() const { return counts_; }

  // Gives up the counter array (the histogram is left empty and unusable) so
  // the inverse colour map can reuse the memory, as libjpeg's jquant2 does.
  std::vector<std::uint32_t> releaseStorage();

 private:
  std::vector<std::uint32_t> counts_;
  std::uint64_t total_ = 0;
};

}  // namespace lattice::quantize
