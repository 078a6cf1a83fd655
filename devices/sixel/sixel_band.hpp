#pragma once
// One six-row band of register numbers as sixel bytes: the driver's whole
// encoding step, separated so that tests, the benchmark and a later per-row
// pre-pass can call it on its own.
//
// Method (the bytes are the measure; docs/sixel.md gives the figures):
//  * A band is drawn as passes, one per register present in it: `#Pc`
//    selects the register, a row of sixels follows, `$` returns to column 0
//    for the next pass, and the driver puts `-` between bands. Registers
//    absent from the band cost nothing. A later sixel overwrites a pixel an
//    earlier one set (xterm's set_sixel, libsixel's decoder, the VT340).
//  * Passes run from the register with the most pixels in the band to the
//    one with the fewest. A pixel whose register is drawn by a LATER pass is
//    free in the earlier ones: whatever they set there is painted over. So
//    the most frequent register, first, can cover whole stretches with one
//    repeated sixel (usually `!W~`), and every pass picks its sixels from
//    what it must set (its own pixels) up to what it may set (its own and
//    the free ones).
//  * encodeRuns() turns one pass into runs: from each column it extends the
//    run while one sixel value lies between the union of the columns' musts
//    and the intersection of their mays (the longest run from there, so the
//    fewest runs, greedily); the value written is the union of the musts.
//    Columns after the last one with a must are not written.
//  * A run of n >= 4 equal sixels is written `!n` and the sixel (n = 3
//    costs three bytes either way, and is written plainly).
//  * `#Pc` is left out when the band's first pass is the register the
//    previous band ended with (the register stays selected across `-`).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "foundation/scanline.hpp"

namespace lattice::sixel {

// Appends the runs of one pass to `out`: must[x] are the bits that pass has
// to set at column x, may[x] (a superset) the bits it is allowed to set.
// Returns the number of runs written.
std::size_t encodeRuns(std::span<const std::uint8_t> must, std::span<const std::uint8_t> may, std::string& out);

// Appends a run of `count` copies of sixel `value` (0..63) to `out`.
void appendRun(std::size_t count, std::uint8_t value, std::string& out);

struct SixelBandStats {
  std::uint64_t passes = 0;  // colour passes
  std::uint64_t runs = 0;
};

class SixelBandEncoder {
 public:
  SixelBandEncoder(int width, int registers);
  // `band` holds `rows` (1..6) rows of `width` register numbers, top first.
  // Appends the band's bytes (without the `-` that follows it) to `out`.
  void encode(std::span<const PaletteIndex> band, int rows, std::string& out);
  const SixelBandStats& stats() const { return stats_; }

 private:
  int width_;
  int lastRegister_ = -1;  // selected at the end of the previous band
  std::vector<std::uint32_t> count_;  // pixels per register in this band
  std::vector<int> order_;            // registers present, most pixels first
  std::vector<std::uint8_t> must_;    // this pass's bits per column
  std::vector<std::uint8_t> later_;   // per column, bits of pixels drawn by passes not yet done
  std::vector<std::uint8_t> may_;
  SixelBandStats stats_;
};

}  // namespace lattice::sixel
