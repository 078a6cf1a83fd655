#pragma once
// Axis-aligned bounding boxes, possibly infinite (a half-space's box is
// unbounded in the directions the plane does not cut off). Every CSG node has
// one; a ray that misses it skips the whole subtree.
#include <algorithm>
#include <limits>

#include "foundation/ray.hpp"

namespace lattice {

template <typename T>
struct Bounds {
  Vec3<T> lo{std::numeric_limits<T>::infinity()};
  Vec3<T> hi{-std::numeric_limits<T>::infinity()};

  static Bounds infinite() {
    return {Vec3<T>(-std::numeric_limits<T>::infinity()), Vec3<T>(std::numeric_limits<T>::infinity())};
  }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  bool isFinite() const {
    for (int a = 0; a < 3; ++a)
      if (!(lo[a] > -std::numeric_limits<T>::infinity() && hi[a] < std::numeric_limits<T>::infinity())) return false;
    return true;
  }
  void extend(const Vec3<T>& p) {
    lo = componentMin(lo, p);
    hi = componentMax(hi, p);
  }
  void extend(const Bounds& b) {
    lo = componentMin(lo, b.lo);
    hi = componentMax(hi, b.hi);
  }
  Vec3<T> center() const { return (lo + hi) * T(0.5); }

  // Slab test: the part [t0, t1] of (tmin, tmax) inside the box, if any.
  // Infinite extents and zero direction components are handled.
  bool clip(const Ray<T>& ray, T tmin, T tmax, T& t0, T& t1) const {
    t0 = tmin;
    t1 = tmax;
    for (int a = 0; a < 3; ++a) {
      T o = ray.origin[a], d = ray.direction[a];
      if (d == T(0)) {
        if (o < lo[a] || o > hi[a]) return false;
        continue;
      }
      const T inv = ray.inverseDirection(a);  // kept by the ray in fixed point (foundation/ray.hpp)
      T ta = (lo[a] - o) * inv, tb = (hi[a] - o) * inv;
      if (ta > tb) std::swap(ta, tb);
      // NaN-safe: (inf - inf) cannot occur since o is finite; max/min keep t0/t1 finite-or-inf.
      t0 = ta > t0 ? ta : t0;
      t1 = tb < t1 ? tb : t1;
      if (t0 > t1) return false;
    }
    return true;
  }
};

// The world-space box of an object-space box under an affine transform
// (all eight corners; an infinite box stays infinite along affected axes).
template <typename T>
Bounds<T> transformBounds(const Bounds<T>& b, const Mat4<T>& m) {
  if (b.empty()) return b;
  if (!b.isFinite()) {
    // Conservative: an unbounded box maps to an unbounded box unless the
    // matrix is a pure translation/scale per axis; keep it simple and safe.
    bool axisAligned = true;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        if (r != c && m[c][r] != T(0)) axisAligned = false;
    if (!axisAligned) return Bounds<T>::infinite();
    Bounds<T> out;
    for (int a = 0; a < 3; ++a) {
      T x0 = b.lo[a] * m[a][a] + m[3][a], x1 = b.hi[a] * m[a][a] + m[3][a];
      if (x0 != x0) x0 = -std::numeric_limits<T>::infinity();  // 0 * inf
      if (x1 != x1) x1 = std::numeric_limits<T>::infinity();
      out.lo[a] = std::min(x0, x1);
      out.hi[a] = std::max(x0, x1);
    }
    return out;
  }
  Bounds<T> out;
  for (int i = 0; i < 8; ++i) {
    Vec3<T> corner((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
    out.extend(transformPoint(m, corner));
  }
  return out;
}

}  // namespace lattice
