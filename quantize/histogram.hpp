#pragma once
// The colour histogram of an 18-bit image, in one of two forms
// (QuantizeOptions::histogram, `--histogram full|small`):
//
// Full: one counter per Color18, 2^18 cells. Counter width: 32 bits,
// saturating at 2^32-1. A 1024x1024 frame has 2^20 pixels, and even a
// 65536x65536 one (2^32) only saturates a single cell of a one-colour image,
// so saturation is a guard, never a working regime. The cost is 2^18 * 4 B =
// 1 MiB; 16-bit counters (libjpeg halves all cells on overflow) would save
// 512 KiB but lose population accuracy on large flat areas, which is exactly
// what a rendered lattice scene has (backgrounds, shaded faces). After the
// palette is built the same 1 MiB is handed to the inverse colour map as its
// cache (releaseStorage), so a run never holds both.
//
// Small: only the colours present, for a microcontroller's RAM (the
// firmware's 256 KiB budget, docs/firmware.md). An open-addressing hash
// table of (colour, count) pairs, 8 B a slot, doubling from 1024 slots while
// it is over 3/4 full, up to kSmallMaxColors colours (kSmallBytes at most,
// 1.5 times that while the last doubling copies); more distinct colours is
// lattice::Error(Usage) naming the way out (--mode sample, or the full form).
// finish() sorts the pairs by colour in place. The counts are the same
// 32-bit saturating counts, and forEach/forEachInBox visit colours in the
// same ascending order in both forms, so the median cut's sums, and with
// them the palette and the whole stream, are the same bit for bit.
//
// Histograms of parts of a picture merge into the whole's (merge, before
// finish): a count is a saturating sum, so min(a + b, max) of the parts'
// saturated counts equals the whole's, in either form and in any order of
// parts. The pipeline counts a kept frame's bands of rows this way, one a
// thread (quantize/frame_bands.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "foundation/scanline.hpp"
#include "quantize/quantize_options.hpp"

namespace lattice::quantize {

class Histogram {
 public:
  static constexpr std::size_t kCells = std::size_t{1} << 18;
  static constexpr std::size_t kBytes = kCells * sizeof(std::uint32_t);
  static constexpr std::size_t kSmallMaxSlots = 8192;
  static constexpr std::size_t kSmallMaxColors = kSmallMaxSlots / 4 * 3;
  static constexpr std::size_t kSmallBytes = kSmallMaxSlots * 8;

  explicit Histogram(HistogramForm form = HistogramForm::Full);

  HistogramForm form() const { return form_; }
  // The bytes this form holds at most (what a memory plan counts).
  static std::size_t bytesOf(HistogramForm form) { return form == HistogramForm::Full ? kBytes : kSmallBytes; }

  void add(Color18 color);
  // Adds every pixel of a row; a colour outside 0..2^18-1 is a caller bug
  // (RowSource18 contract) and throws lattice::Error(Internal).
  void addRow(std::span<const Color18> row);
  // Adds every step-th pixel of the row, starting at column 0.
  void addRowSampled(std::span<const Color18> row, int step);
  // Adds the counts of a histogram of the same form (neither finished). Full
  // form: only the cells [first, last) of the 18-bit cube, so threads can
  // merge disjoint ranges at once; total pixels are added by the call that
  // starts at cell 0. The small form merges every colour whatever the range.
  void merge(const Histogram& part, Color18 first = 0, Color18 last = Color18(kCells));
  // No more colours follow: the small form sorts its pairs here, and reading
  // it before finish() is lattice::Error(Internal).
  void finish();

  std::uint32_t count(Color18 color) const;
  std::uint64_t totalPixels() const { return total_; }
  std::size_t distinctColors() const;
  // Full form only: every cell (empty after releaseStorage).
  std::span<const std::uint32_t> cells() const { return counts_; }

  // visit(colour, count) for every colour present, in ascending Color18 order.
  template <typename Visit>
  void forEach(Visit&& visit) const {
    if (form_ == HistogramForm::Full) {
      for (Color18 c = 0; c < counts_.size(); ++c)
        if (counts_[c] != 0) visit(c, counts_[c]);
    } else {
      for (const Pair& p : sortedPairs())
        visit(p.color, p.count);
    }
  }
  // The same over the colours inside a box of 6-bit channel ranges
  // [lo, hi] (inclusive): ascending Color18 order again.
  template <typename Visit>
  void forEachInBox(const int lo[3], const int hi[3], Visit&& visit) const {
    if (form_ == HistogramForm::Full) {
      for (int r = lo[0]; r <= hi[0]; ++r)
        for (int g = lo[1]; g <= hi[1]; ++g)
          for (int b = lo[2]; b <= hi[2]; ++b) {
            const Color18 c = packColor18(unsigned(r), unsigned(g), unsigned(b));
            if (counts_[c] != 0) visit(c, counts_[c]);
          }
    } else {
      for (const Pair& p : sortedPairs()) {
        const int r = int(red6(p.color)), g = int(green6(p.color)), b = int(blue6(p.color));
        if (r >= lo[0] && r <= hi[0] && g >= lo[1] && g <= hi[1] && b >= lo[2] && b <= hi[2])
          visit(p.color, p.count);
      }
    }
  }

  // Full form: gives up the counter array (the histogram is left empty and
  // unusable) so the inverse colour map can reuse the memory, as libjpeg's
  // jquant2 does. Small form: frees the pairs and returns nothing.
  std::vector<std::uint32_t> releaseStorage();

 private:
  struct Pair {
    Color18 color;
    std::uint32_t count;
  };
  static constexpr Color18 kEmptySlot = ~Color18{0};
  std::span<const Pair> sortedPairs() const;
  void addCount(Color18 color, std::uint32_t n);
  void checkAddable() const;
  void growSmall();

  HistogramForm form_;
  std::vector<std::uint32_t> counts_;  // full form
  std::vector<Pair> pairs_;            // small form: hash slots, then (finished) sorted pairs
  std::size_t used_ = 0;               // small form: distinct colours
  bool finished_ = false;
  std::uint64_t total_ = 0;
};

}  // namespace lattice::quantize
