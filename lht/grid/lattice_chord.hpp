#pragma once
// A world ray carried into a lattice's own coordinates and cut to its box:
// the per-instance work of a lattice leaf (lht/leaf/lattice_leaf.cpp) before any
// table read.
//
// Method and tunables (none tunable; each part gives the last bit the code it
// replaced gave, so pictures do not change):
// * LatticeAffine: world -> lattice as three columns and a translation (3x4,
//   no w row), applied in glm's order for a 4x4 matrix times (p, 1):
//   (m0 x + m1 y) + (m2 z + m3). A direction drops the m3 * 0 term, which can
//   only change the sign of a zero component; the clip tests d == 0 and the
//   rounding maps -0 and +0 alike.
// * clipToCells: the slab test of Bounds::clip over [0, cells] along the
//   whole line, with the three reciprocals taken first (independent
//   divisions the CPU overlaps; in fixed point the ray keeps them, and the
//   leaf's look-up reuses them: foundation/ray.hpp) and Bounds::clip's
//   compare and swap as selects: the same t0 and t1.
// * oneCellBound: in fixed point, a bound the leaf's one cell along the ray,
//   1 / |d|, never exceeds, from the reciprocals the clip has kept: the raw
//   length is floor(sqrt(sum raw^2)) (foundation/vec.hpp), at least the
//   largest |raw| of a component, and the rounded quotient 1 / x does not
//   grow with x, so 1 / |d| <= 1 / max |d_a| = min |1 / d_a|.
// * nearestGridCoordinate: std::round (halves away from zero) without the
//   library call, after the clamp to [0, cells]: truncate, then add one when
//   the fractional part, exact in IEEE arithmetic below 2^24, is at least
//   1/2. Clamping first and rounding after gives what rounding and then
//   clamping did, because the bounds are integers; NaN clamps to 0. The
//   clamp is two selects, so it costs no misprediction at the box's faces.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>
#if defined(__x86_64__)
#include <emmintrin.h>
#endif

#include "foundation/ray.hpp"
#include "foundation/vec.hpp"

namespace lattice::lht {

template <typename T>
class LatticeAffine {
 public:
  explicit LatticeAffine(const Mat4<T>& m) : x_(m[0]), y_(m[1]), z_(m[2]), w_(m[3]) {}
  // From the columns column(0..3) gave (a baked scene's constant data).
  constexpr LatticeAffine(const Vec3<T>& x, const Vec3<T>& y, const Vec3<T>& z, const Vec3<T>& w)
      : x_(x), y_(y), z_(z), w_(w) {}
  // Columns 0..2 (the linear part) and 3 (the translation).
  const Vec3<T>& column(int i) const { return i == 0 ? x_ : i == 1 ? y_ : i == 2 ? z_ : w_; }

  Ray<T> apply(const Ray<T>& ray) const {
    const Vec3<T>& o = ray.origin;
    const Vec3<T>& d = ray.direction;
    return {(x_ * o.x + y_ * o.y) + (z_ * o.z + w_), (x_ * d.x + y_ * d.y) + z_ * d.z};
  }

 private:
  Vec3<T> x_, y_, z_, w_;
};

// The part [t0, t1] of the ray's whole line inside [0, cells]; false if none.
// Locals, not the out-parameters, carry t0 and t1 through the loop, so they
// stay in registers.
template <typename T>
inline bool clipToCells(const Ray<T>& ray, const Vec3<T>& cells, T& t0Out, T& t1Out) {
  T inv[3];
  for (int a = 0; a < 3; ++a) inv[a] = ray.direction[a] == T(0) ? T(0) : ray.inverseDirection(a);
  T t0 = -std::numeric_limits<T>::infinity(), t1 = std::numeric_limits<T>::infinity();
  for (int a = 0; a < 3; ++a) {
    const T o = ray.origin[a];
    if (ray.direction[a] == T(0)) {
      if (o < T(0) || o > cells[a]) return false;
      continue;
    }
    const T toLow = (T(0) - o) * inv[a], toHigh = (cells[a] - o) * inv[a];
    // Bounds::clip's swap as selects (a NaN from 0 * inf falls the same way).
    const bool swap = toLow > toHigh;
    const T ta = swap ? toHigh : toLow, tb = swap ? toLow : toHigh;
    t0 = ta > t0 ? ta : t0;
    t1 = tb < t1 ? tb : t1;
    if (t0 > t1) return false;
  }
  t0Out = t0;
  t1Out = t1;
  return true;
}

// At least T(1) / length(ray.direction) in fixed point (see above), from the
// reciprocals the ray keeps; infinity when no component moves.
template <typename T>
T oneCellBound(const Ray<T>& ray) {
  static_assert(!kIsIeee<T>, "the bound holds for fixed point's exact length and rounding");
  T bound = std::numeric_limits<T>::infinity();
  for (int a = 0; a < 3; ++a)
    if (ray.direction[a] != T(0)) bound = std::min(bound, absolute(ray.inverseDirection(a)));
  return bound;
}

// v > 0 ? v : 0, then that < top ? that : top (NaN and -0 give +0). On
// x86-64 as SSE2's max and min, which are exactly these selects: GCC keeps
// the ternaries as branches, and at a chord's ends, which lie on the box's
// faces, rounding puts a point inside or outside at random.
template <typename T>
T clampSelect(T v, T top) {
#if defined(__x86_64__)
  if constexpr (std::is_same_v<T, double>)
    return _mm_cvtsd_f64(_mm_min_sd(_mm_max_sd(_mm_set_sd(v), _mm_setzero_pd()), _mm_set_sd(top)));
  else if constexpr (std::is_same_v<T, float>)
    return _mm_cvtss_f32(_mm_min_ss(_mm_max_ss(_mm_set_ss(v), _mm_setzero_ps()), _mm_set_ss(top)));
#endif
  const T low = v > T(0) ? v : T(0);
  return low < top ? low : top;
}

// The grid coordinate nearest v, within [0, cells].
template <typename T>
std::uint8_t nearestGridCoordinate(T v, int cells) {
  if constexpr (kIsIeee<T>) {
    const T top = T(cells);
    const T x = clampSelect(v, top);
    const int i = static_cast<int>(x);
    return static_cast<std::uint8_t>(i + (x - T(i) >= T(0.5) ? 1 : 0));
  } else {
    return static_cast<std::uint8_t>(std::clamp(static_cast<int>(roundNearest(v)), 0, cells));
  }
}

}  // namespace lattice::lht
