#pragma once
// What a caller can choose about quantization. The defaults are Heckbert's
// 1982 median cut with no dithering; everything else is a measured extension
// (docs/quantize.md has the figures).
#include <array>

#include "foundation/name_table.hpp"

namespace lattice::quantize {

// Where a box is cut along its longest dimension.
enum class SplitRule {
  Median,    // Heckbert 1982: half the pixels on each side
  Variance,  // the cut that minimises the two halves' summed squared error along that axis
};

enum class Dither {
  None,            // every pixel maps to its nearest palette entry
  FloydSteinberg,  // error diffusion, serpentine, one error row
  Bayer,           // ordered 8x8 threshold matrix: no state between pixels
};

// How the histogram is held (quantize/histogram.hpp): the same palette either way.
enum class HistogramForm {
  Full,   // a counter per 18-bit colour: 1 MiB, any number of colours
  Small,  // only the colours present: at most 64 KiB, up to 6144 colours (the firmware's form)
};

// Their spellings on the command line (`--split`, `--dither`, `--histogram`).
inline constexpr std::array<EnumName<SplitRule>, 2> kSplitRuleNames = {{
    {SplitRule::Median, "median"},
    {SplitRule::Variance, "variance"},
}};
inline constexpr std::array<EnumName<Dither>, 3> kDitherNames = {{
    {Dither::None, "none"},
    {Dither::FloydSteinberg, "fs"},
    {Dither::Bayer, "bayer"},
}};
inline constexpr std::array<EnumName<HistogramForm>, 2> kHistogramFormNames = {{
    {HistogramForm::Full, "full"},
    {HistogramForm::Small, "small"},
}};

struct QuantizeOptions {
  SplitRule split = SplitRule::Median;
  int refineIterations = 0;  // k-means (Lloyd) passes over the histogram after the cut
  Dither dither = Dither::None;
  HistogramForm histogram = HistogramForm::Full;
};

}  // namespace lattice::quantize
