#include "devices/sixel/sixel_run_cost.hpp"

namespace lattice::sixel {
namespace {

int digits(int n) {
  int d = 1;
  for (; n >= 10; n /= 10) ++d;
  return d;
}

}  // namespace

double sixelRunBytes(int length) { return length <= 3 ? double(length) : double(digits(length) + 2); }

quantize::RunCost sixelRunCost(const IndexedImage& picture) {
  const int background = quantize::mostFrequentIndex(picture);
  return [background](int length, int index) {
    if (index == background) return 0.0;
    return sixelRunBytes(length) + 1.0 + digits(index);  // the run, and its `#i`
  };
}

}  // namespace lattice::sixel
