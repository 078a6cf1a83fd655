#pragma once
// A progressive 4125 stream (profile key progressive=on): the picture
// arrives coarse to fine, so a whole picture is on the screen early, and
// the final screen is the one the ordinary stream draws.
//
// Method, after the set-up and the background RR as ever:
//   1. Covers (tek4125_covers.hpp): RR rectangles in bands of 8, then 4,
//      then 2 rows, each in the palette entry nearest its area's mean
//      colour, each level painting only where it brings the screen nearer
//      the picture: a blocky whole picture, then a finer one, for a share
//      of the bytes.
//   2. Rows, each drawn whole by the ordinary row planner
//      (tek4125_rows.hpp) without merging rectangles down rows, overwriting
//      the covers, in the order of the error they remove a byte: a row's
//      squared error against what the covers show over its estimated bytes
//      (an RH and span header, and a few bytes a run), the most first, ties
//      in the order PNG's Adam7 interlaces rows (every 8th row from row 0,
//      then every 8th from row 4, every 4th from row 2, the odd rows).
//      A run of the background colour is skipped only where the covers
//      left the background on every such pixel of the row; elsewhere the
//      row is sent without skipping.
// Forms: RR, RH, RP and RL as the form set allows; no new form, so strict
// stays strict (docs/tek-sources.md: RR, PGPLOT). The row order is free:
// every strict span starts with its own RH.
// Tunables: the covers' (tek4125_covers.hpp); kRowHeaderBytes, kRunBytes.
#include <span>

#include "devices/tek4125/tek4125_rows.hpp"
#include "devices/tek4125/tek4125_writer.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4125 {

inline constexpr double kRowHeaderBytes = 10.0;  // ESC RH xy, ESC RL count
inline constexpr double kRunBytes = 3.0;         // an 8-bit run code of 4 pixels or more

// pixels: the picture's palette indices, row-major (device index = palette
// index + reserved). Returns what was drawn (rectangles include the covers).
Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved);

// The image rows in Adam7's interlaced order.
std::vector<int> progressiveRowOrder(int height);
// The order drawProgressive sends the rows in, given what the covers show
// (shown: device indices, -1 the clear): by error removed a byte, most
// first, ties in progressiveRowOrder's order.
std::vector<int> rowsByGain(std::span<const PaletteIndex> pixels, std::span<const int> shown, const Palette& palette,
                            int reserved, int width, int height);

}  // namespace lattice::tek4125
