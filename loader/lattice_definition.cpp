#include "loader/lattice_definition.hpp"

#include <fmt/format.h>

#include "loader/canonical_toml.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/file/lht_file.hpp"

namespace lattice::lht {

std::uint64_t LatticeDefinition::hashFor(LhtPrecision entryForm) const {
  // From our canonical form of the values (loader/canonical_toml.hpp), never a
  // formatter's output (toml++ 3.3.0's formatter overflowed a float-to-int
  // cast on small numbers in nested arrays, docs/limits.md). "lattice2" marks the
  // key's second form: caches keyed by the formatter's text are refused as
  // rasterized from another definition (docs/lattices.md). The thesis's
  // precision adds nothing to the key.
  const std::string formText =
      entryForm == LhtPrecision::Thesis ? "" : fmt::format(" precision={}", lhtPrecisionName(entryForm));
  return fnv1a64(fmt::format("lattice2 spacing={} oversample={}{} object={}", canonicalDouble(lambda),
                             canonicalDouble(oversample), formText, objectText));
}

const Bounds<double>& LatticeDefinition::objectBounds() const {
  // Every instance asks; building the exact object once is enough.
  std::call_once(bounds_->once, [&] { bounds_->bounds = sceneObject(object, objectText).bounds; });
  return bounds_->bounds;
}

}  // namespace lattice::lht
