#include "lht/grid/octahedral.hpp"

#include <algorithm>
#include <cmath>

namespace lattice::lht {

namespace {

// The octahedral maps treat 0 as positive, so every code has one preimage side.
double signNotZero(double x) { return x >= 0.0 ? 1.0 : -1.0; }
std::int32_t signNotZero(std::int32_t x) { return x >= 0 ? 1 : -1; }
std::int32_t absolute(std::int32_t x) { return x < 0 ? -x : x; }

}  // namespace

std::array<std::int32_t, 3> decodeOctahedral(OctahedralCode code, std::int32_t maxValue) {
  const std::int32_t u = std::clamp(code.u, -maxValue, maxValue);
  const std::int32_t v = std::clamp(code.v, -maxValue, maxValue);
  const std::int32_t z = maxValue - absolute(u) - absolute(v);
  if (z >= 0) return {u, v, z};
  // The lower hemisphere: unfold the corner triangle back under the square.
  return {(maxValue - absolute(v)) * signNotZero(u), (maxValue - absolute(u)) * signNotZero(v), z};
}

OctahedralCode encodeOctahedral(const Vec3d& unit, std::int32_t maxValue) {
  const double l1 = std::abs(unit.x) + std::abs(unit.y) + std::abs(unit.z);
  // A zero or non-finite normal (a degenerate gradient) has no direction to
  // keep: store +z, as the thesis entry decodes an all-zero normal.
  if (!(l1 > 0.0) || !std::isfinite(l1)) return OctahedralCode{0, 0};
  double u = unit.x / l1, v = unit.y / l1;
  if (unit.z < 0.0) {
    const double foldedU = (1.0 - std::abs(v)) * signNotZero(u);
    v = (1.0 - std::abs(u)) * signNotZero(v);
    u = foldedU;
  }
  const Vec3d target = glm::normalize(unit);
  const double m = maxValue;
  OctahedralCode best;
  double bestCosine = -2.0;
  for (const double cu : {std::floor(u * m), std::ceil(u * m)})
    for (const double cv : {std::floor(v * m), std::ceil(v * m)}) {
      const OctahedralCode candidate{std::clamp(static_cast<std::int32_t>(cu), -maxValue, maxValue),
                                     std::clamp(static_cast<std::int32_t>(cv), -maxValue, maxValue)};
      const auto d = decodeOctahedral(candidate, maxValue);
      const double cosine = glm::dot(glm::normalize(Vec3d(d[0], d[1], d[2])), target);
      if (cosine > bestCosine) {
        bestCosine = cosine;
        best = candidate;
      }
    }
  return best;
}

}  // namespace lattice::lht
