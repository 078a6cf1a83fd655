#pragma once
// Shared by the stability tests (tests/render/extremes_test.cpp,
// tests/lht/extremes_test.cpp; docs/stability.md): the three arithmetics by
// name, their stated bounds, exact references in long double, and a way to
// print the measured figures the docs quote.
//
//   LATTICE_PRINT_MEASUREMENTS=1 build/tests/test_render '[extremes]'
//
// prints one line per measured figure (the tests assert the bounds either way).
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "foundation/arithmetics.hpp"
#include "render/shapes/primitive.hpp"

namespace lattice::testing {

using lattice::arithmeticName;  // foundation/arithmetics.hpp

// A bound that depends on the arithmetic: bound<T>(float, double, fixed).
template <typename T>
double bound(double forFloat, double forDouble, double forFixed) {
  if constexpr (std::is_same_v<T, float>) return forFloat;
  else if constexpr (std::is_same_v<T, double>) return forDouble;
  else return forFixed;
}

inline void reportMeasure(const std::string& what, double value, double statedBound) {
  if (std::getenv("LATTICE_PRINT_MEASUREMENTS"))
    std::printf("measured  %-70s %-10.3g bound %.3g\n", what.c_str(), value, statedBound);
}

template <typename T>
Vec3d toDouble(const Vec3<T>& v) {
  return Vec3d(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

// The angle between two directions, accurate for tiny angles too (acos of a
// dot product cannot resolve less than ~1.5e-8 rad in double).
inline double angleBetween(const Vec3d& a, const Vec3d& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// ---------------------------------------------------------------- exact references

using Real = long double;

struct RealVec {
  Real x = 0, y = 0, z = 0;
};

// A ray in an object's local coordinates, in long double: the T ray as the
// renderer holds it (already rounded to T), mapped by worldToLocal.
struct ExactRay {
  RealVec origin, direction;
  RealVec at(Real t) const {
    return {origin.x + direction.x * t, origin.y + direction.y * t, origin.z + direction.z * t};
  }
};

template <typename T>
ExactRay exactRay(const Ray<T>& ray, const Mat4d& worldToLocal) {
  const auto map = [&](const Vec3<T>& v, Real w) {
    const Real in[3] = {static_cast<Real>(static_cast<double>(v.x)), static_cast<Real>(static_cast<double>(v.y)),
                        static_cast<Real>(static_cast<double>(v.z))};
    Real out[3];
    for (int r = 0; r < 3; ++r) {
      Real sum = w * static_cast<Real>(worldToLocal[3][r]);
      for (int c = 0; c < 3; ++c) sum += static_cast<Real>(worldToLocal[c][r]) * in[c];
      out[r] = sum;
    }
    return RealVec{out[0], out[1], out[2]};
  };
  return {map(ray.origin, 1), map(ray.direction, 0)};
}

// The implicit functions of the unit-sized test solids (negative inside).
inline Real sphereFunction(const RealVec& p, Real r) { return p.x * p.x + p.y * p.y + p.z * p.z - r * r; }
inline Real torusFunction(const RealVec& p, Real R, Real r) {
  const Real q = p.x * p.x + p.y * p.y + p.z * p.z + R * R - r * r;
  return q * q - 4 * R * R * (p.x * p.x + p.y * p.y);
}

// Where the ray's line, near parameter tNear, comes closest to (or dips
// into) a solid f < 0 whose surface it grazes: golden-section search for the
// minimum of f along the line in [tNear - reach, tNear + reach] (f is convex
// there for a simple tangent), then bisection for the entry. `clearance` is
// min f / |grad f| there: > 0 misses by about that distance, < 0 dips in.
struct ExactGraze {
  bool hit = false;
  Real tClosest = 0;
  Real enter = 0;      // valid when hit
  Real clearance = 0;  // in the solid's local length units
};

template <typename F>
ExactGraze exactGraze(F f, const ExactRay& ray, Real tNear, Real reach) {
  const auto along = [&](Real t) { return f(ray.at(t)); };
  Real a = tNear - reach, b = tNear + reach;
  const Real phi = (std::sqrt(Real(5)) - 1) / 2;
  for (int i = 0; i < 200; ++i) {
    const Real c = b - phi * (b - a), d = a + phi * (b - a);
    if (along(c) < along(d)) b = d;
    else a = c;
  }
  ExactGraze g;
  g.tClosest = (a + b) / 2;
  const Real fMin = along(g.tClosest);
  // |grad f| at the closest point, by a central difference in each axis.
  const RealVec p = ray.at(g.tClosest);
  const Real h = 1e-7L;
  const Real gx = (f(RealVec{p.x + h, p.y, p.z}) - f(RealVec{p.x - h, p.y, p.z})) / (2 * h);
  const Real gy = (f(RealVec{p.x, p.y + h, p.z}) - f(RealVec{p.x, p.y - h, p.z})) / (2 * h);
  const Real gz = (f(RealVec{p.x, p.y, p.z + h}) - f(RealVec{p.x, p.y, p.z - h})) / (2 * h);
  g.clearance = fMin / std::sqrt(gx * gx + gy * gy + gz * gz);
  g.hit = fMin < 0;
  if (g.hit) {
    Real inside = g.tClosest, outside = tNear - reach;
    for (int i = 0; i < 200; ++i) {
      const Real m = (inside + outside) / 2;
      (along(m) < 0 ? inside : outside) = m;
    }
    g.enter = (inside + outside) / 2;
  }
  return g;
}

}  // namespace lattice::testing
