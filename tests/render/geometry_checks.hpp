#pragma once
// Checks shared by the geometry tests (quartic, shapes, CSG, BVH): a span list
// is compared with an independent point-membership oracle sampled along the
// ray, so merging rules are tested against the set definitions themselves.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <random>

#include "render/shapes/primitive.hpp"

namespace lattice::testing {

using Inside = std::function<bool(const Vec3d&)>;

template <typename T>
Ray<T> makeRay(const Vec3d& o, const Vec3d& d) {
  return {Vec3<T>(o), Vec3<T>(d)};
}

template <typename T>
SpanList<T> spansOf(const Primitive<T>& p, const Ray<T>& ray, T tmin = -std::numeric_limits<T>::infinity(),
                    T tmax = std::numeric_limits<T>::infinity()) {
  SpanList<T> out;
  p.spans(ray, tmin, tmax, out);
  return out;
}

// Spans are sorted, disjoint and non-empty.
template <typename T>
void checkWellFormed(const SpanList<T>& list) {
  for (std::size_t n = 0; n < list.size(); ++n) {
    REQUIRE(list[n].enter.t < list[n].leave.t);
    if (n > 0) REQUIRE(list[n - 1].leave.t < list[n].enter.t);
  }
}

// Samples `samples` points of the ray at t in [t0, t1] and checks that the
// oracle agrees with span membership, except within `margin` of a span end.
template <typename T>
void checkAgainstOracle(const Primitive<T>& p, const Ray<T>& ray, const Inside& inside, double t0, double t1,
                        int samples = 400, double margin = 1e-4) {
  SpanList<T> list = spansOf(p, ray);
  checkWellFormed(list);
  for (int n = 0; n <= samples; ++n) {
    double t = t0 + (t1 - t0) * n / samples;
    bool inSpan = false, nearEnd = false;
    for (const Span<T>& s : list) {
      if (t > double(s.enter.t) && t < double(s.leave.t)) inSpan = true;
      if (std::abs(t - double(s.enter.t)) < margin || std::abs(t - double(s.leave.t)) < margin) nearEnd = true;
    }
    if (nearEnd) continue;
    Vec3d point = Vec3d(ray.origin) + Vec3d(ray.direction) * t;
    INFO("t = " << t << " point = (" << point.x << ", " << point.y << ", " << point.z << ")");
    REQUIRE(inSpan == inside(point));
  }
}

inline Vec3d randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Vec3d v(g(rng), g(rng), g(rng));
  return v / glm::length(v);
}

}  // namespace lattice::testing
