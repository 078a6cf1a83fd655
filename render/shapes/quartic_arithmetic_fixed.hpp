#pragma once
// The quartic leaf's fixed-point arithmetic (Fixed32): the specialisation of
// render/shapes/quartic_arithmetic.hpp that render/shapes/quartic.cpp uses for
// --arith fixed (docs/fixed-point.md).
//
// Method and tunables:
// * Shapes are rescaled before conversion (prepare, in
//   render/shapes/quartic_arithmetic_fixed.cpp): Q31.32 has an absolute resolution
//   of 2^-32, so coefficients far from 1 lose their digits; the object space
//   is scaled by a power of two near the object's size and the polynomial by
//   a power of two, the transform taking the scale back.
// * Directions go through the linear part of world -> object scaled by a
//   power of two to entries of about 1 (entries of 2^-13 for a radius of 1e4
//   kept 19 of 32 fraction bits: 6e-5 relative error in t, measured), and t
//   takes the power back. Points use the scaled matrix while no partial sum
//   can saturate: coordinates up to 2^29 / (largest row sum).
// * Substituted rays are checked against the range (kChecksRange): where the
//   coefficients' bound leaves Q31.32 the ray misses instead of returning
//   saturated garbage.
#include <algorithm>
#include <limits>

#include "foundation/fixed.hpp"
#include "render/shapes/quartic_arithmetic.hpp"

namespace lattice {

template <>
class QuarticArithmetic<Fixed32> {
 public:
  using T = Fixed32;
  static constexpr bool kChecksRange = true;
  static constexpr const char* kRangeHint =
      " (--arith fixed holds magnitudes below 2^31 = 2.1e9; use --arith double)";

  static QuarticPlacement prepare(const QuarticPlacement& placement);
  // One raw step: fixed point has no ulp of varying size.
  static T nextToward(T x, T to) {
    return x < to ? x + std::numeric_limits<T>::epsilon() : x - std::numeric_limits<T>::epsilon();
  }

  QuarticArithmetic() = default;
  explicit QuarticArithmetic(const Mat4d& worldToObject);

  bool toObject(const Ray<T>& worldRay, const Vec3<T>& pivot, ObjectRay<T>& out) const {
    const Vec3<T> origin = toObjectPoint(worldRay.origin);
    const Vec3<T> direction = worldToObjectDirection_ * worldRay.direction;
    out.len = lattice::length(direction);
    if (!(out.len > T(0)) || !finite(out.len)) return false;
    out.u = direction / out.len;
    const T toPivot = lattice::dot(pivot - origin, out.u);
    out.t0 = sToT(toPivot, out.len);
    out.base = origin + out.u * toPivot;
    return true;
  }
  T sToT(T s, T len) const { return (s / len) * tPerScaledS_; }

 private:
  Vec3<T> toObjectPoint(const Vec3<T>& p) const {
    const T m = std::max({absolute(p.x), absolute(p.y), absolute(p.z)});
    if (m > scaledPointLimit_) return transformPoint(worldToObject_, p);
    return (worldToObjectDirection_ * p) * matrixScale_ + objectTranslation_;
  }

  Mat4<T> worldToObject_{};
  // The linear part of world -> object divided by matrixScale_ (a power of
  // two), its translation, the largest coordinate a point may have to go
  // through it, and 1 / matrixScale_, which turns s / len into t.
  Mat3<T> worldToObjectDirection_{};
  T matrixScale_{1};
  Vec3<T> objectTranslation_{};
  T scaledPointLimit_{0};
  T tPerScaledS_{1};
};

}  // namespace lattice
