#pragma once
// The 4027's paint pots are HLS colours in the Tektronix convention, which the
// sixel device shares: the conversion lives in devices/tek_hls.hpp, named here
// for the 4027's code.
#include "devices/tek_hls.hpp"

namespace lattice::tek4027 {

using devices::Hls;
using devices::kHlsRoundTripMaxDelta;
using devices::rgbToTekHls;
using devices::tekHlsToRgb;

}  // namespace lattice::tek4027
