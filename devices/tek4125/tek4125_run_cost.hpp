#pragma once
// What a run of one colour costs in a 4125 stream, for rate-distortion runs
// (quantize/rate_distortion_runs.hpp). Method: the row planner's own
// estimates (tek4125_rows.cpp): a run is the cheaper of its RL run codes
// (split at the form set's longest code, plus the repeated `ESC RL count` of
// a capped RL) and, where the form set allows RP at this depth, its raster
// bits; a run of the picture's most frequent colour may instead be skipped,
// which inside a row costs the next span's header (`ESC RH xy ESC RL count`:
// 12 bytes in strict). Counted as free, a skip let the programme turn
// near-background runs into background that the planner then had to draw as
// codes anyway. Other span headers and
// rectangles are left out: they are shared by many runs.
#include "devices/tek4125/tek4125_profile.hpp"
#include "quantize/rate_distortion_runs.hpp"

namespace lattice::tek4125 {

quantize::RunCost tek4125RunCost(const Tek4125Profile& profile, const IndexedImage& picture);
// The same for a picture of `colours` palette entries whose most frequent
// entry is `background` (-1: none skipped).
quantize::RunCost tek4125RunCost(const Tek4125Profile& profile, int colours, int background);

}  // namespace lattice::tek4125
