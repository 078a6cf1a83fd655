#pragma once
// What the quartic leaf (render/shapes/quartic.cpp) does differently per arithmetic:
// how a shape is prepared before its coefficients are converted to T, and
// how a world ray is carried into the shape's object space.
//
// Method: this generic version serves the IEEE types: the polynomial as
// given, the ray through the world -> object matrix, t = s / len. An
// arithmetic that needs otherwise specialises QuarticArithmetic in its own
// file, as fixed point does (render/shapes/quartic_arithmetic_fixed.hpp), and
// render/shapes/quartic.cpp includes it; the leaf itself has no per-type branch.
#include <cmath>

#include "foundation/bounds.hpp"
#include "foundation/ray.hpp"
#include "foundation/vec.hpp"
#include "render/shapes/quartic.hpp"

namespace lattice {

// A quartic as a leaf builds it: the polynomial, its object box, its transform.
struct QuarticPlacement {
  QuarticPolynomial f;
  Bounds<double> bounds;
  Mat4d objectToWorld;
};

// A world ray in a leaf's object space: base + u s with u unit; the world t
// of s is t0 + sToT(s, len).
template <typename T>
struct ObjectRay {
  Vec3<T> base, u;
  T len, t0;
};

template <typename T>
class QuarticArithmetic {
 public:
  // Whether a substituted ray must be checked against the range of T before
  // its roots are solved (see QuarticLeaf::withinRange).
  static constexpr bool kChecksRange = false;
  // Appended to "too large for the renderer's number type" messages.
  static constexpr const char* kRangeHint = "";

  static QuarticPlacement prepare(QuarticPlacement placement) { return placement; }
  // The neighbour of x towards `to`.
  static T nextToward(T x, T to) { return std::nextafter(x, to); }

  QuarticArithmetic() = default;
  explicit QuarticArithmetic(const Mat4d& worldToObject) : worldToObject_(worldToObject) {}

  // False when the ray has no usable direction in object space. `pivot` is
  // the object point rays are re-based at (t0: closest approach to it).
  bool toObject(const Ray<T>& worldRay, const Vec3<T>& pivot, ObjectRay<T>& out) const {
    const Ray<T> ray = worldRay.transformed(worldToObject_);
    out.len = lattice::length(ray.direction);
    if (!(out.len > T(0)) || !finite(out.len)) return false;
    out.u = ray.direction / out.len;
    out.t0 = lattice::dot(pivot - ray.origin, out.u) / out.len;
    out.base = ray.origin + ray.direction * out.t0;
    return true;
  }
  T sToT(T s, T len) const { return s / len; }

 private:
  Mat4<T> worldToObject_{};
};

}  // namespace lattice
