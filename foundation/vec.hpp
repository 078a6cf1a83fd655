#pragma once
// Vector and matrix types of the per-pixel path. The scalar T is a template
// parameter everywhere on that path (float, double and the fixed-point
// Fixed32, render/fixed.hpp), so nothing per pixel hard-wires double. Scene
// set-up (parsing, building transforms) is done in double with GLM and
// converted once.
//
// GLM's geometric and common functions (dot, length, normalize, min, max,
// clamp) static_assert that the scalar is an IEEE type, so the per-pixel code
// calls the helpers below instead: for float and double they ARE the GLM
// functions (results unchanged to the bit); for fixed point they are integer
// code (length sums the squares exactly in 128 bits, so it never overflows
// for any representable vector).
#include <algorithm>
#include <cmath>
#include <type_traits>

#include <glm/glm.hpp>

#include "foundation/fixed.hpp"
#include "foundation/fixed_math.hpp"

namespace lattice {

template <typename T>
using Vec3 = glm::vec<3, T, glm::defaultp>;
template <typename T>
using Mat3 = glm::mat<3, 3, T, glm::defaultp>;
template <typename T>
using Mat4 = glm::mat<4, 4, T, glm::defaultp>;

using Vec3d = Vec3<double>;
using Mat4d = Mat4<double>;

template <typename T>
inline constexpr bool kIsIeee = std::is_floating_point_v<T>;

// Points and directions through an affine 4x4 matrix (no projective divide).
template <typename T>
inline Vec3<T> transformPoint(const Mat4<T>& m, const Vec3<T>& p) {
  return Vec3<T>(m * glm::vec<4, T, glm::defaultp>(p, T(1)));
}
template <typename T>
inline Vec3<T> transformDirection(const Mat4<T>& m, const Vec3<T>& d) {
  return Vec3<T>(m * glm::vec<4, T, glm::defaultp>(d, T(0)));
}

// --- Scalars ---------------------------------------------------------------
template <typename T>
inline T absolute(T x) {
  if constexpr (kIsIeee<T>) return std::abs(x);
  else return abs(x);
}
template <typename T>
inline bool finite(T x) {
  if constexpr (kIsIeee<T>) return std::isfinite(x);
  else return isfinite(x);
}
template <typename T>
inline T roundNearest(T x) {
  if constexpr (kIsIeee<T>) return std::round(x);
  else return round(x);
}
template <typename T>
inline T power(T x, T y) {
  if constexpr (kIsIeee<T>) return std::pow(x, y);
  else return pow(x, y);
}

// --- Vectors ---------------------------------------------------------------
template <typename T>
inline T dot(const Vec3<T>& a, const Vec3<T>& b) {
  if constexpr (kIsIeee<T>) return glm::dot(a, b);
  else return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
inline T length(const Vec3<T>& v) {
  if constexpr (kIsIeee<T>) {
    return glm::length(v);
  } else {
    // |v| from the exact sum of the squared raw values: no intermediate can
    // overflow, and sqrt(sum raw^2) is the raw length.
    UInt128 sum = 0;
    for (int a = 0; a < 3; ++a) {
      const auto r = v[a].raw();
      const UInt128 m = static_cast<UInt128>(r < 0 ? -r : r);
      sum += m * m;
    }
    const UInt128 root = isqrt(sum);
    return T::fromRaw(root > static_cast<UInt128>(T::kMaxRaw) ? T::kMaxRaw : static_cast<typename T::Raw>(root));
  }
}
template <typename T>
inline Vec3<T> normalize(const Vec3<T>& v) {
  if constexpr (kIsIeee<T>) return glm::normalize(v);
  else return v / length(v);
}
template <typename T>
inline Vec3<T> componentMin(const Vec3<T>& a, const Vec3<T>& b) {
  if constexpr (kIsIeee<T>) return glm::min(a, b);
  else return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T>
inline Vec3<T> componentMax(const Vec3<T>& a, const Vec3<T>& b) {
  if constexpr (kIsIeee<T>) return glm::max(a, b);
  else return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <typename T>
inline Vec3<T> clamp01(const Vec3<T>& v) {
  if constexpr (kIsIeee<T>) return glm::clamp(v, Vec3<T>(T(0)), Vec3<T>(T(1)));
  else return componentMin(componentMax(v, Vec3<T>(T(0))), Vec3<T>(T(1)));
}

}  // namespace lattice
