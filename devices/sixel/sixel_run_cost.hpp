#pragma once
// What a run of one colour in one image row costs in a sixel stream, for
// rate-distortion runs (quantize/rate_distortion_runs.hpp).
//
// Method: a row is one of the six rows of a band, and its run of L pixels
// of register i is L columns of register i's pass over the band
// (sixel_band.hpp). Those columns cost what the band encoder writes for a
// run: L sixels up to 3, else `!L` and the sixel (digits of L + 2 bytes);
// and a new colour in a line costs its `#i` (digits of i + 1). A run of the
// picture's most frequent register is free: a band's most frequent register
// is drawn first, as one `!W~` over the whole band, whatever its runs.
// The six rows of a band share their pass, so this over-counts a run whose
// neighbours above and below have the same edges; it only steers (the real
// encoder's bytes are what count), and lambda absorbs the scale.
#include "foundation/indexed_image.hpp"
#include "quantize/rate_distortion_runs.hpp"

namespace lattice::sixel {

// The bytes of a sixel run of `length` columns: the encoder's appendRun.
double sixelRunBytes(int length);

quantize::RunCost sixelRunCost(const IndexedImage& picture);

}  // namespace lattice::sixel
