// The lattice leaf's firstHit, firstEnter and anyHit (lht/leaf/lattice_leaf.cpp)
// skip the span list, the exit read and unused normals; they must answer
// exactly what Primitive's defaults derive from the leaf's spans(), for rays
// from outside, from inside, starting on the surface (the self-shadow rule)
// and ending short of it, in double, float and fixed point.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

#include "foundation/fixed.hpp"
#include "lht/grid/lattice_chord.hpp"
#include "lht/leaf/lattice_leaf.hpp"
#include "lht/raster/lattice_object.hpp"
#include "tests/lht/raster_support.hpp"

using namespace lattice;
using namespace lattice::lht;
using lattice::testing::rasterizeObject;

namespace {

template <typename T>
struct Tally {
  int rays = 0, hits = 0, enters = 0, insides = 0, shadowed = 0, fromSurface = 0;
};

// Both answers of each query for one ray; counts what was exercised.
template <typename T>
void compareQueries(const Primitive<T>& leaf, const Ray<T>& ray, T tmin, T tmax, Tally<T>& tally) {
  ++tally.rays;
  Hit<T> fast, slow;
  const bool f = leaf.firstHit(ray, tmin, tmax, fast);
  const bool s = leaf.Primitive<T>::firstHit(ray, tmin, tmax, slow);
  REQUIRE(f == s);
  if (f) {
    ++tally.hits;
    REQUIRE(fast.t == slow.t);
    REQUIRE(fast.normal == slow.normal);
    REQUIRE(fast.material == slow.material);
  }
  bool fastInside = false, slowInside = false;
  Hit<T> fastEnter, slowEnter;
  const bool fe = leaf.firstEnter(ray, tmin, tmax, fastEnter, fastInside);
  const bool se = leaf.Primitive<T>::firstEnter(ray, tmin, tmax, slowEnter, slowInside);
  REQUIRE(fe == se);
  REQUIRE(fastInside == slowInside);
  if (fe) {
    ++tally.enters;
    REQUIRE(fastEnter.t == slowEnter.t);
    REQUIRE(fastEnter.normal == slowEnter.normal);
  }
  if (fastInside) ++tally.insides;
  const bool shadow = leaf.anyHit(ray, tmin, tmax);
  REQUIRE(shadow == leaf.Primitive<T>::anyHit(ray, tmin, tmax));
  if (shadow) ++tally.shadowed;
}

template <typename T>
Tally<T> randomRays(const Primitive<T>& leaf, const Bounds<double>& box, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  const Vec3d size = box.hi - box.lo;
  const auto inBox = [&](double grow) {
    return box.lo - size * grow + Vec3d(unit(rng), unit(rng), unit(rng)) * size * (1 + 2 * grow);
  };
  Tally<T> tally;
  for (int i = 0; i < 4000; ++i) {
    const Vec3d from = inBox(i % 2 ? 0.0 : 1.0);  // half start inside the box
    const Vec3d to = inBox(0.0);
    Vec3d d = to - from;
    if (i % 7 == 0) d.y = 0.0;  // parallel to a face now and then
    if (glm::length(d) < 1e-9) continue;
    const double tmax = i % 3 == 0 ? 0.7 : 1e6;  // shadow rays stop short
    compareQueries<T>(leaf, Ray<T>{Vec3<T>(from), Vec3<T>(d)}, T(1e-6), T(tmax), tally);
  }
  // Shadow rays from points on the surface: the self-shadow rule decides.
  for (int i = 0; i < 2000; ++i) {
    const Vec3d from = inBox(1.0), to = inBox(0.0);
    const Ray<T> ray{Vec3<T>(from), Vec3<T>(to - from)};
    Hit<T> hit;
    if (!leaf.firstHit(ray, T(0), T(1e6), hit)) continue;
    ++tally.fromSurface;
    const Vec3<T> p = ray.at(hit.t);
    const Vec3d toward(sym(rng), sym(rng), sym(rng));
    compareQueries<T>(leaf, Ray<T>{p, Vec3<T>(toward)}, T(1e-6), T(i % 2 ? 1e6 : 0.05), tally);
  }
  return tally;
}

template <typename T>
void checkArithmetic(LatticeLookup lookup) {
  const LatticeObject capsule = capsuleObject(0.3, 2.0);
  const auto lht = rasterizeObject(capsule, 0.4, 2.0);
  const Mat4d place = glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.5)) *
                      glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 1, 0))) *
                      glm::scale(Mat4d(1.0), Vec3d(1.0, 1.5, 0.8));
  const auto leaf = makeLatticeLeaf<T>(lht, place, 5, true, nullptr, lookup);
  const Bounds<double> world{Vec3d(leaf->bounds().lo), Vec3d(leaf->bounds().hi)};
  const Tally<T> tally = randomRays<T>(*leaf, world, 17);
  INFO("rays " << tally.rays << ", hits " << tally.hits << ", enters " << tally.enters << ", inside "
               << tally.insides << ", shadowed " << tally.shadowed << ", from the surface " << tally.fromSurface);
  // Every branch was taken: the comparison above is not vacuous.
  CHECK(tally.hits > 200);
  CHECK(tally.enters > 200);
  CHECK(tally.insides > 20);
  CHECK(tally.fromSurface > 200);
  CHECK(tally.shadowed < tally.rays);
}

}  // namespace

TEST_CASE("lattice leaf queries: firstHit, firstEnter and anyHit equal the span-derived answers") {
  SECTION("double") { checkArithmetic<double>(LatticeLookup::Thesis); }
  SECTION("float") { checkArithmetic<float>(LatticeLookup::Thesis); }
  SECTION("fixed") { checkArithmetic<Fixed32>(LatticeLookup::Thesis); }
  SECTION("double, blended look-up") { checkArithmetic<double>(LatticeLookup::Blend); }
}

TEST_CASE("lattice chord: the cheap rounding is std::round's, clamped, on halves and neighbours") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> wide(-3.0, 260.0);
  std::vector<double> values = {-0.5, -0.0, 0.0, 0.49999999999999994, 0.5, 1.5, 2.5, 254.5, 255.0, 255.5, 300.0};
  for (int i = 0; i < 20000; ++i) values.push_back(wide(rng));
  for (int k = 0; k < 256; ++k)
    for (double v : {k + 0.5, k - 0.5, std::nextafter(k + 0.5, 0.0), std::nextafter(k + 0.5, 1e9)}) values.push_back(v);
  for (double v : values) {
    const int expected = std::clamp(static_cast<int>(std::round(v)), 0, 255);
    INFO("v = " << v);
    REQUIRE(nearestGridCoordinate<double>(v, 255) == expected);
    const float vf = static_cast<float>(v);
    REQUIRE(nearestGridCoordinate<float>(vf, 255) == std::clamp(static_cast<int>(std::round(vf)), 0, 255));
  }
  CHECK(nearestGridCoordinate<double>(std::nan(""), 40) == 0);
  CHECK(nearestGridCoordinate<float>(std::nanf(""), 40) == 0);
  CHECK(nearestGridCoordinate<double>(7.3, 5) == 5);
  // The clamp's selects at the ends a chord lies on, and beyond them.
  CHECK(nearestGridCoordinate<double>(-std::numeric_limits<double>::infinity(), 40) == 0);
  CHECK(nearestGridCoordinate<double>(std::numeric_limits<double>::infinity(), 40) == 40);
  CHECK(nearestGridCoordinate<double>(std::nextafter(40.0, 1e9), 40) == 40);
  CHECK(nearestGridCoordinate<double>(std::nextafter(0.0, -1.0), 40) == 0);
  CHECK(nearestGridCoordinate<float>(std::numeric_limits<float>::infinity(), 40) == 40);
  CHECK(nearestGridCoordinate<float>(-std::numeric_limits<float>::infinity(), 40) == 0);
}

TEST_CASE("lattice chord: the clip gives Bounds::clip's t0 and t1 to the bit, and the affine map Ray::transformed's") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-20.0, 40.0);
  const Vec3d cells(16, 9, 30);
  const Bounds<double> box{Vec3d(0.0), cells};
  const Mat4d m = glm::translate(Mat4d(1.0), Vec3d(3.5, -1.25, 7)) * glm::rotate(Mat4d(1.0), 0.3, Vec3d(0.2, 1, 0.4)) *
                  glm::scale(Mat4d(1.0), Vec3d(2, 0.5, 3));
  const LatticeAffine<double> affine(m);
  const double inf = std::numeric_limits<double>::infinity();
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3d o(u(rng), u(rng), u(rng)), d(u(rng), u(rng), u(rng));
    if (i % 5 == 0) d[i % 3] = 0.0;           // parallel to a pair of faces
    if (i % 11 == 0) o[i % 3] = cells[i % 3];  // starting on a face
    const Ray<double> ray{o, d};
    const Ray<double> a = affine.apply(ray), b = ray.transformed(m);
    REQUIRE(a.origin == b.origin);
    for (int k = 0; k < 3; ++k) REQUIRE(a.direction[k] == b.direction[k]);  // -0 == +0: the only difference allowed
    double s0 = 0, s1 = 0, r0 = 0, r1 = 0;
    const bool fast = clipToCells(ray, cells, s0, s1);
    const bool slow = box.clip(ray, -inf, inf, r0, r1);
    REQUIRE(fast == slow);
    if (!fast) continue;
    ++inside;
    REQUIRE(s0 == r0);
    REQUIRE(s1 == r1);
  }
  CHECK(inside > 2000);
}

TEST_CASE("lattice chord: in fixed point one cell along the ray never exceeds oneCellBound") {
  // The look-up answers "at least one cell past tmin" from the bound where
  // it settles it, so the bound must hold for every direction: components of
  // every size, zeros among them, and directions along one axis (equality).
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int equal = 0;
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 44) - 24);
    Vec3<Fixed32> d(Fixed32(unit(rng) * scale), Fixed32(unit(rng) * scale), Fixed32(unit(rng) * scale));
    if (i % 5 == 0) d[i % 3] = Fixed32(0);
    if (i % 11 == 0) d = Vec3<Fixed32>(Fixed32(0), d.y, Fixed32(0));
    if (d == Vec3<Fixed32>(Fixed32(0))) continue;
    const Ray<Fixed32> ray{Vec3<Fixed32>(Fixed32(0)), d};
    const Fixed32 cell = Fixed32(1) / length(d), bound = oneCellBound(ray);
    INFO("d = " << double(d.x) << ", " << double(d.y) << ", " << double(d.z));
    REQUIRE(cell <= bound);
    if (cell == bound) ++equal;
  }
  CHECK(equal > 1000);  // tight where the direction lies along an axis
}
