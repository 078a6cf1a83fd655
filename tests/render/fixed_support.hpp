#pragma once
// Comparing a Fixed32 render with the double render of the same scene: the
// measure docs/fixed-point.md quotes (PSNR over all channels, and the share
// of channels more than 4 levels of 255 apart).
#include <cmath>
#include <cstdlib>

#include "io/png.hpp"

namespace lattice::testing {

struct FixedVsDouble {
  double psnr = 0.0;           // dB; +inf when identical
  double farFraction = 0.0;    // channels with |difference| > 4
  int maxDelta = 0;
};

inline FixedVsDouble compareRenders(const RgbImage& fixedImage, const RgbImage& doubleImage) {
  FixedVsDouble out;
  double squared = 0.0;
  long far = 0;
  for (std::size_t i = 0; i < fixedImage.rgb.size(); ++i) {
    const int d = std::abs(int(fixedImage.rgb[i]) - int(doubleImage.rgb[i]));
    squared += double(d) * d;
    if (d > 4) ++far;
    if (d > out.maxDelta) out.maxDelta = d;
  }
  const double n = double(fixedImage.rgb.size());
  out.psnr = squared == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / (squared / n));
  out.farFraction = double(far) / n;
  return out;
}

}  // namespace lattice::testing
