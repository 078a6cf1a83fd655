#include "lht/lattice_definition.hpp"

#include <fmt/format.h>

#include "lht/lattice_object.hpp"
#include "lht/lht_file.hpp"

namespace lattice::lht {

std::uint64_t LatticeDefinition::hashFor(LhtPrecision form) const {
  // The thesis's precision adds nothing, so caches written before the
  // precision existed (all of them thesis) keep their hash.
  const std::string formText =
      form == LhtPrecision::Thesis ? "" : fmt::format(" precision={}", lhtPrecisionName(form));
  return fnv1a64(fmt::format("lattice spacing={:.17g} oversample={:.17g}{} object={}", lambda, oversample, formText,
                             objectText));
}

const Bounds<double>& LatticeDefinition::objectBounds() const {
  // Every instance asks; building the exact object once is enough.
  std::call_once(bounds_->once, [&] { bounds_->bounds = sceneObject(object, objectText).bounds; });
  return bounds_->bounds;
}

}  // namespace lattice::lht
