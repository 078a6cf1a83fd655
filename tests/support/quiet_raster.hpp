#pragma once
// Rasterizing options for tests: no progress bar on the test's output, and
// a thread count (0: all cores) where a test compares thread counts.
#include "lht/raster/rasterize.hpp"

namespace lattice::testing {

inline lht::RasterOptions quietRaster(unsigned threads = 0) {
  lht::RasterOptions options;
  options.progress = false;
  options.threads = threads;
  return options;
}

}  // namespace lattice::testing
