#pragma once
// Rasterizing a test object into a table the lattice leaf can use, quietly
// (no progress bar), for the lattice tests.
#include <memory>

#include "lht/raster/lattice_object.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::testing {

// The object rasterized in `box` (any box: one from the object's bounds, or
// one of chosen cell counts).
inline std::shared_ptr<const lht::LhtFile> rasterizeInBox(const lht::LatticeObject& object, const lht::LatticeBox& box) {
  auto file = std::make_shared<lht::LhtFile>();
  file->box = box;
  lht::RasterOptions options;
  options.progress = false;
  const lht::RasterResult raster = lht::rasterize(file->box, *object.primitive, options);
  file->objectHash = object.hash();
  file->pairs = raster.stats.pairs;
  file->hits = raster.stats.hits;
  file->table = lht::LatticeHashTable(raster.hits);
  return file;
}

// The object rasterized in the box its bounds, lambda and f_lat give.
inline std::shared_ptr<const lht::LhtFile> rasterizeObject(const lht::LatticeObject& object, double lambda,
                                                           double oversample) {
  return rasterizeInBox(object, lht::LatticeBox(object.bounds, lambda, oversample));
}

}  // namespace lattice::testing
