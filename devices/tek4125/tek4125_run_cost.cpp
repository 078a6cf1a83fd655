#include "devices/tek4125/tek4125_run_cost.hpp"

#include <algorithm>

#include "devices/tek4125/tek4125_encoding.hpp"

namespace lattice::tek4125 {

quantize::RunCost tek4125RunCost(const Tek4125Profile& profile, const IndexedImage& picture) {
  return tek4125RunCost(profile, static_cast<int>(picture.colormap.size()), quantize::mostFrequentIndex(picture));
}

quantize::RunCost tek4125RunCost(const Tek4125Profile& profile, int colours, int background) {
  const Tek4125Forms& forms = profile.formSet();
  const int reserved = profile.reserved;
  // The driver's choices (tek4125_driver.cpp): 4 bits when the colours fit.
  const int bits = profile.pixelBitsFor(colours);
  const bool raster = bits == 4 || !forms.rasterOnlyAtFourBits;
  const bool runLength = forms.runLength;
  const int maxRun = std::max(1, (forms.maxRunCode + 1) / (1 << bits) - 1);
  const double perCode = forms.runCodeBytesPerRl > 0 ? 1.0 + 5.0 / forms.runCodeBytesPerRl : 1.0;
  // Skipping a background run inside a row means a new span after it: an
  // RH (and its xy) and the RL or RP header again.
  const double restart = 3 + (forms.fullXy ? 5 : 3) + 3 + 1;
  return [=](int length, int index) {
    double best = raster ? length * bits / 6.0 : 1e9;
    if (runLength) {
      double codes = 0;
      for (int left = length; left > 0; left -= maxRun)
        codes += intLength(std::min(left, maxRun) << bits | (index + reserved));
      best = std::min(best, codes * perCode);
    }
    return index == background ? std::min(best, restart) : best;
  };
}

}  // namespace lattice::tek4125
