#include "devices/tek4027/tek4027_run_cost.hpp"

namespace lattice::tek4027 {

quantize::RunCost tek4027RunCost(const IndexedImage& picture) {
  const int background = quantize::mostFrequentIndex(picture);
  return [background](int /*length*/, int index) { return index == background ? 0.0 : kBytesPerRun; };
}

}  // namespace lattice::tek4027
