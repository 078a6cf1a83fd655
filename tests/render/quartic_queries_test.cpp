// The quartic leaf's own firstHit, firstEnter and anyHit (render/shapes/quartic.cpp)
// against what Primitive's defaults derive from spans(): the same t, normal
// and material bit for bit, in every arithmetic, on shapes with one to four
// crossings, unbounded solids and rays that start inside.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include "foundation/fixed.hpp"
#include "geometry_checks.hpp"
#include "render/shapes/quartic.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;
using lattice::testing::makeRay;
using lattice::testing::spansOf;

namespace {

template <typename T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}
template <typename T>
bool sameHit(const Hit<T>& a, const Hit<T>& b) {
  return sameBits(a.t, b.t) && sameBits(a.normal.x, b.normal.x) && sameBits(a.normal.y, b.normal.y) &&
         sameBits(a.normal.z, b.normal.z) && a.material == b.material;
}

}  // namespace

TEMPLATE_TEST_CASE("quartic leaves answer firstHit, firstEnter and anyHit as spans() would", "[quartic]", float, double,
                   Fixed32) {
  using T = TestType;
  const QuarticShape shapes[] = {sphere(1.0), torus(1.0, 0.3), halfSpace(Vec3d(0.3, 1.0, -0.2), -0.5), cylinder(0.7),
                                 cone(0.8)};
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0), window(-1.0, 6.0);
  int hits = 0, enters = 0, insides = 0;
  MaterialId material = 1;
  for (const QuarticShape& shape : shapes) {
    auto leaf = makeQuarticLeaf<T>(shape.f, shape.bounds, Mat4d(1.0), material++);
    for (int n = 0; n < 3000; ++n) {
      const Vec3d origin(coordinate(rng), coordinate(rng), coordinate(rng));
      const Vec3d target(coordinate(rng) * 0.4, coordinate(rng) * 0.4, coordinate(rng) * 0.4);
      const Ray<T> ray = makeRay<T>(origin, target - origin);
      double a = window(rng), b = window(rng);
      if (a > b) std::swap(a, b);
      const T tmin = static_cast<T>(n % 4 == 0 ? 0.0 : a), tmax = n % 3 == 0 ? std::numeric_limits<T>::infinity() : static_cast<T>(b);
      const SpanList<T> list = spansOf(*leaf, ray, tmin, tmax);

      Hit<T> expected, got;
      const bool crossing = firstCrossing(list, tmin, tmax, expected);
      REQUIRE(leaf->firstHit(ray, tmin, tmax, got) == crossing);
      if (crossing) REQUIRE(sameHit(got, expected));
      REQUIRE(leaf->anyHit(ray, tmin, tmax) == crossing);
      hits += crossing;

      // Primitive::firstEnter's reading of the first span.
      bool expectedInside = false, inside = false;
      bool expectedEnter = false;
      if (!list.empty()) {
        if (list[0].enter.t <= tmin) expectedInside = true;
        else if (list[0].enter.t < tmax) expectedEnter = true;
      }
      Hit<T> enter;
      REQUIRE(leaf->firstEnter(ray, tmin, tmax, enter, inside) == expectedEnter);
      REQUIRE(inside == expectedInside);
      if (expectedEnter) REQUIRE(sameHit(enter, list[0].enter));
      enters += expectedEnter;
      insides += expectedInside;
    }
  }
  // The cases are all there: crossings, enters ahead and rays starting inside.
  REQUIRE(hits > 1000);
  REQUIRE(enters > 500);
  REQUIRE(insides > 200);
}
