// The build-time half of the quartic leaf's fixed-point arithmetic
// (render/shapes/quartic_arithmetic_fixed.hpp): rescaling a shape and the scaled
// world -> object matrices. Done once per leaf, in double.
#include "render/shapes/quartic_arithmetic_fixed.hpp"

#include <cmath>

namespace lattice {

namespace {

// An unbounded shape (a floor, a cylinder) has no box to measure; its size is
// the length at which its constant term balances its highest-degree terms:
// 1e4 for the floor y > -1e4, the radius for a cylinder. Without it, that
// floor's y coefficient became 2^-13 after normalization and its hits were
// off by 5e-6 relative (measured). 0 when there is no constant term.
double naturalLength(const QuarticPolynomial& f) {
  const int degree = f.degree();
  double top = 0.0;
  for (int n = 1; n < QuarticPolynomial::kTerms; ++n) {
    const auto e = QuarticPolynomial::exponents(n);
    if (e[0] + e[1] + e[2] == degree) top = std::max(top, std::abs(f.a[static_cast<std::size_t>(n)]));
  }
  if (degree < 1 || !(top > 0.0)) return 0.0;
  return std::pow(std::abs(f.a[0]) / top, 1.0 / degree);
}

}  // namespace

// A torus of radius 1e4 has an x^4 coefficient of 1e-8, 43 units of 2^-32.
// So the object space is re-scaled by a power of two S near the object's size
// (x = S x') and the polynomial by a power of two (same zero set and signs)
// so its largest coefficient is about 1; the transform takes S back, so t and
// the world geometry are unchanged.
QuarticPlacement QuarticArithmetic<Fixed32>::prepare(const QuarticPlacement& placement) {
  const QuarticPolynomial& f = placement.f;
  const Bounds<double>& objectBounds = placement.bounds;
  double size = 0.0;
  bool finiteBox = !objectBounds.empty();
  for (int ax = 0; ax < 3; ++ax) {
    if (!std::isfinite(objectBounds.lo[ax]) || !std::isfinite(objectBounds.hi[ax])) finiteBox = false;
    else size = std::max({size, std::abs(objectBounds.lo[ax]), std::abs(objectBounds.hi[ax])});
  }
  if (!finiteBox) size = naturalLength(f);
  const double s = size > 0.0 && std::isfinite(size) ? std::exp2(std::round(std::log2(size))) : 1.0;
  QuarticPlacement out{{}, objectBounds, placement.objectToWorld};
  double largest = 0.0;
  for (int n = 0; n < QuarticPolynomial::kTerms; ++n) {
    const auto e = QuarticPolynomial::exponents(n);
    const double v = f.a[static_cast<std::size_t>(n)] * std::pow(s, e[0] + e[1] + e[2]);
    out.f.a[static_cast<std::size_t>(n)] = v;
    if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  }
  if (largest > 0.0) out.f *= std::exp2(-std::round(std::log2(largest)));
  if (!objectBounds.empty()) out.bounds = {objectBounds.lo / s, objectBounds.hi / s};  // +-inf stays
  Mat4d scale(1.0);
  scale[0][0] = scale[1][1] = scale[2][2] = s;
  out.objectToWorld = placement.objectToWorld * scale;
  return out;
}

QuarticArithmetic<Fixed32>::QuarticArithmetic(const Mat4d& worldToObject) : worldToObject_(worldToObject) {
  const glm::dmat3 directionMatrix(worldToObject);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(directionMatrix[c][r]));
  // Only matrices with small entries lose bits; large ones keep them.
  const double shift = std::min(0.0, std::round(std::log2(largest)));
  const glm::dmat3 scaled = directionMatrix * std::exp2(-shift);
  worldToObjectDirection_ = Mat3<T>(scaled);
  tPerScaledS_ = T(std::exp2(-shift));
  // Each coordinate's magnitude may be at most a quarter of the range divided
  // by the largest row sum for no partial sum to saturate.
  double rowSum = 0.0;
  for (int r = 0; r < 3; ++r)
    rowSum = std::max(rowSum, std::abs(scaled[0][r]) + std::abs(scaled[1][r]) + std::abs(scaled[2][r]));
  scaledPointLimit_ = T(std::exp2(29) / std::max(rowSum, 1.0));
  objectTranslation_ = Vec3<T>(Vec3d(worldToObject[3]));
  matrixScale_ = T(std::exp2(shift));
}

}  // namespace lattice
