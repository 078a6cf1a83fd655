// The closed-form half-space (render/shapes/plane_leaf.cpp) against the quartic leaf
// it replaces in float and double, on thousands of random rays per placement:
// rays from inside and outside, grazing rays (nearly parallel to the plane)
// and rays exactly parallel to it, inside and outside. The spans must match
// end for end: the same infinite end, t within a stated tolerance (relative
// 1e-5 in float, 1e-13 in double; looser across the plane for grazing rays), the normal
// identical (both leaves compute it from the same gradient), the material.
// The leaf's own firstHit / firstEnter / anyHit must equal what its spans say.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include "geometry_checks.hpp"
#include "foundation/error.hpp"
#include "render/shapes/plane_leaf.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

struct Counts {
  int crossings = 0, misses = 0, grazing = 0;
  int insideSamples = 0, outsideSamples = 0;  // of the grazing rays
};

// Inside by the spans at t.
template <typename T>
bool insideAt(const SpanList<T>& list, double t) {
  for (const Span<T>& s : list)
    if (double(s.enter.t) < t && t < double(s.leave.t)) return true;
  return false;
}

// A crossing's t is as well conditioned as the angle to the plane allows:
// for rays at least 0.01 (in the sine) off the plane, |t_plane - t_quartic|
// <= tol * (1 + |t|); down to a sine of 1e-4 the two points must agree
// across the plane, |dt (n . d)| <= tol * (1 + |o| + |t d|), and may slide
// along it. Below that (parallel to rounding) one form may cross at
// |t| ~ 1e6 or more where the other is parallel: both must then agree with
// the exact plane on 64 points of the ray within 10 units of its origin,
// except points within 1e3 tol of the plane.
template <typename T>
void compareSpans(const Primitive<T>& plane, const Primitive<T>& quartic, const Ray<T>& ray, const Vec3d& n,
                  double constant, double tol, Counts& c) {
  const Vec3d o(ray.origin), d(ray.direction);
  const double sine = std::abs(glm::dot(n, d)) / glm::length(d);
  if (sine < 1e-4) {
    ++c.grazing;
    const SpanList<T> a = spansOf(plane, ray), b = spansOf(quartic, ray);
    for (int k = 0; k < 64; ++k) {
      const double t = -10.0 + 20.0 * k / 63.0;
      const double f = glm::dot(n, o + d * t) + constant;
      if (std::abs(f) < 1e3 * tol) continue;
      INFO("t " << t << ", f " << f << ", sine " << sine);
      REQUIRE(insideAt(a, t) == (f < 0));
      REQUIRE(insideAt(b, t) == (f < 0));
      ++(f < 0 ? c.insideSamples : c.outsideSamples);
    }
    return;
  }
  const SpanList<T> a = spansOf(plane, ray), b = spansOf(quartic, ray);
  REQUIRE(a.size() == b.size());
  if (a.empty()) {
    ++c.misses;
    return;
  }
  REQUIRE(a.size() == 1);
  for (const auto& [pa, pb] : {std::pair{a[0].enter, b[0].enter}, std::pair{a[0].leave, b[0].leave}}) {
    if (!std::isfinite(double(pb.t)) || !std::isfinite(double(pa.t))) {
      REQUIRE(pa.t == pb.t);  // the same unbounded end
      continue;
    }
    const double t = double(pb.t), dt = std::abs(double(pa.t) - t);
    INFO("t " << double(pa.t) << " against the quartic's " << t << ", sine to the plane " << sine);
    if (sine > 0.01) REQUIRE(dt <= tol * (1.0 + std::abs(t)));
    REQUIRE(dt * std::abs(glm::dot(n, d)) <= tol * (1.0 + glm::length(o) + std::abs(t) * glm::length(d)));
    REQUIRE(pa.normal == pb.normal);
    REQUIRE(pa.material == pb.material);
  }
  if (std::isfinite(double(a[0].enter.t)) || std::isfinite(double(a[0].leave.t)))
    ++c.crossings;
}

template <typename T>
void compareQueries(const Primitive<T>& plane, const Ray<T>& ray, T tmin, T tmax) {
  Hit<T> fast, slow;
  const bool f = plane.firstHit(ray, tmin, tmax, fast);
  REQUIRE(f == plane.Primitive<T>::firstHit(ray, tmin, tmax, slow));
  if (f) REQUIRE((fast.t == slow.t && fast.normal == slow.normal));
  bool fastInside = false, slowInside = false;
  const bool e = plane.firstEnter(ray, tmin, tmax, fast, fastInside);
  REQUIRE(e == plane.Primitive<T>::firstEnter(ray, tmin, tmax, slow, slowInside));
  REQUIRE(fastInside == slowInside);
  if (e) REQUIRE(fast.t == slow.t);
  REQUIRE(plane.anyHit(ray, tmin, tmax) == plane.Primitive<T>::anyHit(ray, tmin, tmax));
}

template <typename T>
Counts randomRays(const QuarticShape& shape, const Mat4d& place, double tol) {
  const auto plane = makePlaneLeaf<T>(shape.f, shape.bounds, place, 4);
  const auto quartic = makeQuarticLeaf<T>(shape.f, shape.bounds, place, 4);
  REQUIRE(plane->bounds().lo == quartic->bounds().lo);
  REQUIRE(plane->bounds().hi == quartic->bounds().hi);
  // The world plane, to aim grazing and parallel rays along it.
  const Vec3d a(shape.f.a[1], shape.f.a[2], shape.f.a[3]);
  const Vec3d unscaled = glm::inverseTranspose(glm::dmat3(place)) * a;
  const Vec3d n = glm::normalize(unscaled);
  const double constant = (shape.f.a[0] - glm::dot(unscaled, Vec3d(place[3]))) / glm::length(unscaled);
  const Vec3d along = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0)));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  Counts c;
  for (int i = 0; i < 6000; ++i) {
    const Vec3d o(u(rng), u(rng), u(rng));
    Vec3d d(u(rng), u(rng), u(rng));
    if (i % 4 == 1) d = along * 3.0 + glm::cross(n, along) * u(rng);                 // exactly parallel (to rounding)
    if (i % 4 == 2) d = glm::normalize(along + n * (std::pow(10.0, -1 - i % 7) * u(rng)));  // grazing, 1e-1 to 1e-7
    if (glm::length(d) == 0.0) continue;
    const Ray<T> ray = makeRay<T>(o, d);
    compareSpans<T>(*plane, *quartic, ray, n, constant, tol, c);
    compareQueries<T>(*plane, ray, T(1e-4), i % 3 ? T(1e30) : T(1.5));
    compareQueries<T>(*plane, ray, T(-2), T(2));
  }
  return c;
}

}  // namespace

TEMPLATE_TEST_CASE("the closed-form half-space gives the quartic half-space's spans", "[shapes][plane]", float, double) {
  using T = TestType;
  const double tol = std::is_same_v<T, float> ? 1e-5 : 1e-13;
  struct Case {
    QuarticShape shape;
    Mat4d place;
  };
  const Case cases[] = {
      {halfSpace(Vec3d(0, 1, 0), -0.6), Mat4d(1)},  // the scenes' floor (an axis-aligned box on one side)
      {halfSpace(Vec3d(0.3, -1, 2), 0.7),
       glm::translate(Mat4d(1), Vec3d(0.5, -1, 2)) * glm::rotate(Mat4d(1), 0.7, glm::normalize(Vec3d(1, 2, 0.5))) *
           glm::scale(Mat4d(1), Vec3d(1.0, 2.5, 0.5))},
      {halfSpace(Vec3d(0, 0, -3), 1.0), glm::scale(glm::translate(Mat4d(1), Vec3d(0, 0, 1)), Vec3d(2, 2, 0.25))},
  };
  for (const Case& k : cases) {
    const Counts c = randomRays<T>(k.shape, k.place, tol);
    INFO("crossings " << c.crossings << ", misses " << c.misses << ", grazing " << c.grazing << " (samples inside "
                      << c.insideSamples << ", outside " << c.outsideSamples << ")");
    CHECK(c.crossings > 3000);
    CHECK(c.grazing > 1500);
    CHECK(c.insideSamples > 10000);  // parallel and grazing rays inside the solid
    CHECK(c.outsideSamples > 10000);
  }
}

TEST_CASE("the closed-form half-space refuses what the quartic leaf refuses") {
  const QuarticShape floor = halfSpace(Vec3d(0, 1, 0), 0.0);
  Mat4d singular(1);
  singular[1][1] = 0.0;
  CHECK_THROWS_AS(makePlaneLeaf<double>(floor.f, floor.bounds, singular, 0), Error);
  CHECK_THROWS_AS(makeQuarticLeaf<double>(floor.f, floor.bounds, singular, 0), Error);
  CHECK_THROWS_AS(makePlaneLeaf<double>(sphere(1.0).f, sphere(1.0).bounds, Mat4d(1), 0), Error);  // not a plane
}
