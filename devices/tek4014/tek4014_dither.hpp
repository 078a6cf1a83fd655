#pragma once
// Rows of palette indices to rows of lit and dark dots, for a monochrome
// screen, one row at a time (the whole frame is never held).
//
// Method and tunables:
//  - Each palette entry's luminance is computed once, in linear light (sRGB
//    decoded, then Rec. 709 weights 0.2126 R + 0.7152 G + 0.0722 B), because
//    the eye averages the light of lit dots, not their encoded values: a
//    half-lit area must come out as half the dots.
//  - Floyd-Steinberg: error diffusion with weights 7/16 (next in the row),
//    3/16, 5/16, 1/16 (the row below), the row walked left to right and right
//    to left in turn (serpentine) so the errors do not drift one way. Two
//    rows of errors are kept: O(width) floats.
//  - Ordered: the 8x8 Bayer matrix; a dot is lit when its luminance exceeds
//    (rank + 0.5) / 64. No state; stable under small palette changes.
//  - Threshold: lit when luminance >= 0.5.
#include <cstdint>
#include <span>
#include <vector>

#include "devices/tek4014/tek4014_profile.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4014 {

// Linear-light luminance of an sRGB colour, 0..1.
float linearLuminance(Rgb8 colour);

class RowDither {
 public:
  RowDither(Tek4014Dither method, int width, const Palette& palette);
  // Row y (0 = top) of palette indices to `lit` (size width: 1 lit, 0 dark).
  // Rows must come in order 0, 1, 2, ...
  void row(int y, std::span<const PaletteIndex> indices, std::span<std::uint8_t> lit);

 private:
  Tek4014Dither method_;
  int width_;
  std::vector<float> luminance_;  // per palette index
  std::vector<float> error_;      // this row's incoming error, width + 2 (a guard each side)
  std::vector<float> next_;       // the next row's
};

}  // namespace lattice::tek4014
