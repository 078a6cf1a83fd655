// The reciprocal direction a fixed-point ray keeps (foundation/ray.hpp): the
// box tests read it instead of dividing, so it must be T(1) / direction to
// the bit, whenever and however often it is asked, and a ray made from
// another (transformed, or a new direction) must not carry the old one.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "foundation/ray.hpp"

using namespace lattice;

namespace {

template <typename T>
bool sameBits(const Vec3<T>& a, const Vec3<T>& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Directions with zero, tiny, unit-sized and large components of both signs.
template <typename T>
std::vector<Vec3<T>> directions() {
  std::mt19937_64 rng(1988);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3<T>> out{Vec3<T>(T(0), T(1), T(0)), Vec3<T>(T(-0.25), T(0), T(3))};
  for (int i = 0; i < 3000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    Vec3<T> d(T(unit(rng) * scale), T(unit(rng) * scale), T(unit(rng) * scale));
    if (i % 7 == 0) d[i % 3] = T(0);
    out.push_back(d);
  }
  return out;
}

template <typename T>
void checkKeptInverse() {
  for (const Vec3<T>& d : directions<T>()) {
    const Ray<T> ray{Vec3<T>(T(0.5), T(-2), T(1)), d};
    const Vec3<T> expected = T(1) / d;
    REQUIRE(sameBits(ray.inverseDirection(), expected));
    for (int a = 0; a < 3; ++a) {
      const T component = ray.inverseDirection(a), want = T(1) / d[a];
      REQUIRE(std::memcmp(&component, &want, sizeof want) == 0);
    }
    REQUIRE(sameBits(ray.inverseDirection(), expected));  // asked again: the same
    const Ray<T> copy = ray;                               // a copy carries it
    REQUIRE(sameBits(copy.inverseDirection(), expected));
    // Another direction is another ray with its own reciprocal.
    const Ray<T> turned{ray.origin, d * T(2) + Vec3<T>(T(1), T(0), T(0))};
    REQUIRE(sameBits(turned.inverseDirection(), T(1) / turned.direction));
    Mat4<T> stretch(T(1));
    stretch[0][0] = T(2);
    const Ray<T> moved = ray.transformed(stretch);
    REQUIRE(sameBits(moved.inverseDirection(), T(1) / moved.direction));
  }
}

}  // namespace

TEST_CASE("ray: the reciprocal direction a ray gives is T(1) / direction, bit for bit") {
  checkKeptInverse<Fixed32>();
  checkKeptInverse<double>();
  checkKeptInverse<float>();
}

TEST_CASE("ray: only fixed point keeps the reciprocal, float and double rays stay two vectors") {
  CHECK(sizeof(Ray<float>) == 2 * sizeof(Vec3<float>));
  CHECK(sizeof(Ray<double>) == 2 * sizeof(Vec3<double>));
  CHECK(sizeof(Ray<Fixed32>) > 2 * sizeof(Vec3<Fixed32>));
}
