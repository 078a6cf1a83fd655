#pragma once
// A progressive 4125 stream (profile key progressive=on): the picture
// arrives coarse to fine, so a whole picture is on the screen early, and
// the final screen is the one the ordinary stream draws.
//
// Method, after the set-up and the background RR as ever:
//   1. Covers: the picture is cut into bands of kBandRows rows. For each
//      band, its middle row, simplified by rate-distortion runs
//      (quantize/rate_distortion_runs.hpp) under RR costs at kCoverLambda,
//      is sent as one RR per run not of the background colour, each
//      kBandRows tall: a blocky picture for a small share of the bytes.
//   2. Rows, interlaced as PNG's Adam7 interlaces rows: every 8th row from
//      row 0, then every 8th from row 4, every 4th from row 2, then the odd
//      rows. Each row is drawn whole by the ordinary row planner
//      (tek4125_rows.hpp) without merging rectangles down rows, overwriting
//      its band's cover. A run of the background colour is skipped only
//      where the covers left the background on every such pixel of the row;
//      elsewhere the row is sent without skipping.
// Forms: RR, RH, RP and RL as the form set allows; no new form, so strict
// stays strict (docs/tek-sources.md: RR, PGPLOT). The row order is free:
// every strict span starts with its own RH.
// Tunables: kBandRows (8, Adam7's first pass), kCoverLambda, kRectangleBytes.
#include <span>

#include "devices/tek4125/tek4125_rows.hpp"
#include "devices/tek4125/tek4125_writer.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4125 {

inline constexpr int kBandRows = 8;
inline constexpr double kCoverLambda = 4000.0;
inline constexpr double kRectangleBytes = 15.0;  // ESC RR, two five-byte xy, an index

// pixels: the picture's palette indices, row-major (device index = palette
// index + reserved). Returns what was drawn (rectangles include the covers).
Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved);

// The image rows in the order drawProgressive sends them.
std::vector<int> progressiveRowOrder(int height);

}  // namespace lattice::tek4125
