#pragma once
// What a run of one colour costs in a 4027 stream, for rate-distortion runs
// (quantize/rate_distortion_runs.hpp). Method: the 4027 draws every pixel
// that is not the erase colour by vectors (tek4027_runs.hpp), so a run of
// the picture's most frequent colour (the erase pot) is free and any other
// costs about one vector's worth of coordinates whatever its length.
// Tunable: kBytesPerRun, two decimal coordinate pairs of a chained polyline
// ("123 45 200 45," less what chaining shares), an estimate that only steers.
#include "devices/tek4027/tek4027_profile.hpp"
#include "quantize/rate_distortion_runs.hpp"

namespace lattice::tek4027 {

inline constexpr double kBytesPerRun = 8.0;

quantize::RunCost tek4027RunCost(const IndexedImage& picture);

}  // namespace lattice::tek4027
