#pragma once
// A progressive 4125 stream (profile key progressive=on): the picture
// arrives coarse to fine, so a whole picture is on the screen early, and
// the final screen is the one the ordinary stream draws.
//
// Method, after the set-up and the background RR as ever:
//   1. Covers (tek4125_covers.hpp): RR rectangles in bands of 16, then 8
//      rows, each in the palette entry nearest its area's mean colour, each
//      level painting only where it brings the screen nearer the picture: a
//      blocky whole picture for a small share of the bytes.
//   2. Draft rows: every row once, simplified by rate-distortion runs
//      (quantize/rate_distortion_runs.hpp) under the stream's own run costs
//      at kDraftLambda, drawn by the ordinary row planner (tek4125_rows.hpp):
//      a row in about a third of its exact bytes, as near the picture as a
//      wire budget's pictures. They are the covers of the last pass.
//   3. Exact rows: every row as it is, the planner skipping the runs the
//      screen already shows (what the covers and the draft left right), so
//      the final screen is the ordinary stream's.
//   Rows of steps 2 and 3 go in the order of the error they remove a byte:
//   a row's squared error against what the screen shows over its estimated
//   bytes (an RH and span header, and a few bytes a run), most first, ties
//   in the order PNG's Adam7 interlaces rows (every 8th row from row 0, then
//   every 8th from row 4, every 4th from row 2, the odd rows). Rectangles
//   are not merged down rows, since rows no longer come in order.
// The price: more bytes in all than the ordinary stream (Plate 6 at
// 512x512: 226,707 B against 164,444 B), for a picture that is near the
// final one long before the ordinary stream's half-way point
// (bench/strict-quality.sh has the figures).
// Forms: RR, RH, RP and RL as the form set allows; no new form, so strict
// stays strict (docs/tek-sources.md: RR, PGPLOT). The row order is free:
// every strict span starts with its own RH.
// Tunables: the covers' (tek4125_covers.hpp); kDraftLambda; kRowHeaderBytes,
// kRunBytes.
#include <span>

#include "devices/tek4125/tek4125_covers.hpp"
#include "devices/tek4125/tek4125_rows.hpp"
#include "quantize/rate_distortion_runs.hpp"
#include "devices/tek4125/tek4125_writer.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4125 {

// Squared 8-bit RGB error a byte is worth in the draft rows. Plate 6, 25 %
// into the stream (bench/strict-quality.sh): 3000 23.5 dB, 4000 23.6 dB
// (226,707 B), 5000 23.6 dB with a coarser picture at half-way.
inline constexpr double kDraftLambda = 4000.0;
inline constexpr double kRowHeaderBytes = 10.0;  // ESC RH xy, ESC RL count
inline constexpr double kRunBytes = 3.0;         // an 8-bit run code of 4 pixels or more

// What a progressive stream sends before the exact rows, worked out once
// for all of a picture's encodings (the driver tries several).
struct ProgressivePlan {
  std::vector<CoverRectangle> covers;
  std::vector<PaletteIndex> drafts;  // the picture, every row simplified by rate-distortion runs
};

// pixels: the picture's palette indices, row-major (device index = palette
// index + reserved); background: the device index painted under the whole
// picture (-1: none, the page's clear); fullXy: the form set's; draftCost:
// the stream's run costs (tek4125_run_cost.hpp).
ProgressivePlan planProgressive(int width, int height, int background, bool fullXy,
                                std::span<const PaletteIndex> pixels, const Palette& palette, int reserved,
                                const quantize::RunCost& draftCost);

// Sends the covers, the draft rows and the exact rows of `plan` (made for
// the layout's picture and background). Returns what was drawn (rectangles
// include the covers).
Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved, const ProgressivePlan& plan);

// Draws every row of `rows` (the picture's size) once, in rowsByGain's order
// for `pixels`, the runs the screen already shows skipped; `shown` is
// updated to what was drawn.
void drawRows(Tek4125RowPlanner& planner, std::span<const PaletteIndex> pixels, std::span<const PaletteIndex> rows,
              const Palette& palette, int reserved, std::span<int> shown);

// The image rows in Adam7's interlaced order.
std::vector<int> progressiveRowOrder(int height);
// The order drawProgressive sends the rows in, given what the covers show
// (shown: device indices, -1 the clear): by error removed a byte, most
// first, ties in progressiveRowOrder's order.
std::vector<int> rowsByGain(std::span<const PaletteIndex> pixels, std::span<const int> shown, const Palette& palette,
                            int reserved, int width, int height);

}  // namespace lattice::tek4125
