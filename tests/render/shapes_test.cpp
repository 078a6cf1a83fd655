// Every quartic preset against its analytic intersections and normals, the
// CSG capsule against the distance-to-segment definition, and silhouette
// sweeps (torus, sphere of radius 1e6) that must show no speckles.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "geometry_checks.hpp"
#include "render/shapes/composite_shapes.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <typename T>
PrimitivePtr<T> leafOf(const QuarticShape& s, const Mat4d& m = Mat4d(1)) {
  return makeQuarticLeaf<T>(s.f, s.bounds, m, 1);
}

// One span expected: its ends and the normals there.
template <typename T>
void expectSpan(const Span<T>& s, double t0, double t1, const Vec3d& n0, const Vec3d& n1) {
  const double eps = std::is_same_v<T, float> ? 1e-4 : 1e-9;
  if (std::isinf(t0)) {
    REQUIRE(std::isinf(s.enter.t));
    REQUIRE(s.enter.t < 0);
  } else {
    REQUIRE(double(s.enter.t) == Approx(t0).margin(eps));
    REQUIRE(glm::length(Vec3d(s.enter.normal) - glm::normalize(n0)) < 10 * eps);
  }
  if (std::isinf(t1)) {
    REQUIRE(std::isinf(s.leave.t));
    REQUIRE(s.leave.t > 0);
  } else {
    REQUIRE(double(s.leave.t) == Approx(t1).margin(eps));
    REQUIRE(glm::length(Vec3d(s.leave.normal) - glm::normalize(n1)) < 10 * eps);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("half-space: plane crossing, unbounded span, box cut only when axis-aligned", "[shapes]", float,
                   double) {
  using T = TestType;
  QuarticShape s = halfSpace(Vec3d(0, 0, 2), 2);  // z < 1
  REQUIRE(s.bounds.hi.z == 1);
  REQUIRE(std::isinf(s.bounds.lo.z));
  auto leaf = leafOf<T>(s);
  SpanList<T> down = spansOf(*leaf, makeRay<T>(Vec3d(0.3, 0.2, 5), Vec3d(0, 0, -1)));
  REQUIRE(down.size() == 1);
  expectSpan(down[0], 4, kInf, Vec3d(0, 0, 1), {});
  SpanList<T> up = spansOf(*leaf, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(up.size() == 1);
  expectSpan(up[0], -kInf, 6, {}, Vec3d(0, 0, 1));
  // Ray above the plane, parallel to it: misses the box entirely.
  REQUIRE(spansOf(*leaf, makeRay<T>(Vec3d(0, 0, 2), Vec3d(1, 0, 0))).empty());

  QuarticShape tilted = halfSpace(Vec3d(1, 1, 0), 0);
  REQUIRE_FALSE(tilted.bounds.isFinite());
  REQUIRE(std::isinf(tilted.bounds.hi.x));
  SpanList<T> cross = spansOf(*leafOf<T>(tilted), makeRay<T>(Vec3d(-3, 0, 0), Vec3d(1, 0, 0)));
  REQUIRE(cross.size() == 1);
  expectSpan(cross[0], -kInf, 3, {}, Vec3d(1, 1, 0));
  REQUIRE_THROWS_AS(halfSpace(Vec3d(0), 1), Error);
}

TEMPLATE_TEST_CASE("sphere: analytic entry/exit and radial normals", "[shapes]", float, double) {
  using T = TestType;
  auto leaf = leafOf<T>(sphere(2));
  SpanList<T> axis = spansOf(*leaf, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(axis.size() == 1);
  expectSpan(axis[0], 3, 7, Vec3d(0, 0, -1), Vec3d(0, 0, 1));
  SpanList<T> off = spansOf(*leaf, makeRay<T>(Vec3d(-5, 1, 0), Vec3d(1, 0, 0)));
  REQUIRE(off.size() == 1);
  double h = std::sqrt(3.0);
  expectSpan(off[0], 5 - h, 5 + h, Vec3d(-h, 1, 0), Vec3d(h, 1, 0));
  REQUIRE(spansOf(*leaf, makeRay<T>(Vec3d(-5, 2.1, 0), Vec3d(1, 0, 0))).empty());
  REQUIRE_THROWS_AS(sphere(0), Error);
  REQUIRE_THROWS_AS(sphere(-1), Error);
  REQUIRE_THROWS_AS(sphere(std::numeric_limits<double>::quiet_NaN()), Error);
}

TEMPLATE_TEST_CASE("ellipsoid: semi-axes along each axis and gradient normals", "[shapes]", float, double) {
  using T = TestType;
  auto leaf = leafOf<T>(ellipsoid(1, 2, 3));
  SpanList<T> x = spansOf(*leaf, makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0)));
  SpanList<T> y = spansOf(*leaf, makeRay<T>(Vec3d(0, -5, 0), Vec3d(0, 1, 0)));
  SpanList<T> z = spansOf(*leaf, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE((x.size() == 1 && y.size() == 1 && z.size() == 1));
  expectSpan(x[0], 4, 6, Vec3d(-1, 0, 0), Vec3d(1, 0, 0));
  expectSpan(y[0], 3, 7, Vec3d(0, -1, 0), Vec3d(0, 1, 0));
  expectSpan(z[0], 2, 8, Vec3d(0, 0, -1), Vec3d(0, 0, 1));
  // Off-axis: at y = 1, x^2 = 1 - 1/4; normal ~ (x/1, y/4, 0).
  SpanList<T> o = spansOf(*leaf, makeRay<T>(Vec3d(-5, 1, 0), Vec3d(1, 0, 0)));
  REQUIRE(o.size() == 1);
  double xh = std::sqrt(0.75);
  expectSpan(o[0], 5 - xh, 5 + xh, Vec3d(-xh, 0.25, 0), Vec3d(xh, 0.25, 0));
  REQUIRE_THROWS_AS(ellipsoid(1, 0, 1), Error);
}

TEMPLATE_TEST_CASE("cylinder: infinite along z, radial normals", "[shapes]", float, double) {
  using T = TestType;
  QuarticShape s = cylinder(1);
  REQUIRE(s.bounds.hi.x == 1);
  REQUIRE(std::isinf(s.bounds.hi.z));
  auto leaf = leafOf<T>(s);
  SpanList<T> across = spansOf(*leaf, makeRay<T>(Vec3d(-5, 0.5, 7), Vec3d(1, 0, 0)));
  REQUIRE(across.size() == 1);
  double xh = std::sqrt(0.75);
  expectSpan(across[0], 5 - xh, 5 + xh, Vec3d(-xh, 0.5, 0), Vec3d(xh, 0.5, 0));
  SpanList<T> along = spansOf(*leaf, makeRay<T>(Vec3d(0.2, 0.1, 0), Vec3d(0, 0, 1)));
  REQUIRE(along.size() == 1);
  expectSpan(along[0], -kInf, kInf, {}, {});
  REQUIRE(spansOf(*leaf, makeRay<T>(Vec3d(1.5, 0, 0), Vec3d(0, 0, 1))).empty());
}

TEMPLATE_TEST_CASE("cone: double cone of given slope", "[shapes]", float, double) {
  using T = TestType;
  auto leaf = leafOf<T>(cone(0.5));
  // At z = 2 the radius is 1; the gradient there is (2x, 2y, -2 * 0.25 z).
  SpanList<T> across = spansOf(*leaf, makeRay<T>(Vec3d(-5, 0, 2), Vec3d(1, 0, 0)));
  REQUIRE(across.size() == 1);
  expectSpan(across[0], 4, 6, Vec3d(-2, 0, -1), Vec3d(2, 0, -1));
  // Along the axis the ray is inside both nappes: one span through the apex.
  SpanList<T> along = spansOf(*leaf, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(along.size() == 1);
  REQUIRE(std::isinf(along[0].enter.t));
  REQUIRE(std::isinf(along[0].leave.t));
  // Parallel to the axis at x = 1: inside where |z| > 2.
  SpanList<T> side = spansOf(*leaf, makeRay<T>(Vec3d(1, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(side.size() == 2);
  expectSpan(side[0], -kInf, 3, {}, Vec3d(2, 0, 1));
  expectSpan(side[1], 7, kInf, Vec3d(2, 0, -1), {});
}

TEMPLATE_TEST_CASE("paraboloid: opens towards +z", "[shapes]", float, double) {
  using T = TestType;
  QuarticShape s = paraboloid(1);
  REQUIRE(s.bounds.lo.z == 0);
  auto leaf = leafOf<T>(s);
  SpanList<T> across = spansOf(*leaf, makeRay<T>(Vec3d(-5, 0, 4), Vec3d(1, 0, 0)));
  REQUIRE(across.size() == 1);
  expectSpan(across[0], 3, 7, Vec3d(-4, 0, -1), Vec3d(4, 0, -1));
  SpanList<T> up = spansOf(*leaf, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(up.size() == 1);
  expectSpan(up[0], 5, kInf, Vec3d(0, 0, -1), {});
}

TEMPLATE_TEST_CASE("hyperboloids of one and two sheets", "[shapes]", float, double) {
  using T = TestType;
  auto one = leafOf<T>(hyperboloid(1, 2, true));
  // Waist radius 1 at z = 0; at z = 2 the radius is sqrt(2).
  SpanList<T> waist = spansOf(*one, makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0)));
  REQUIRE(waist.size() == 1);
  expectSpan(waist[0], 4, 6, Vec3d(-1, 0, 0), Vec3d(1, 0, 0));
  SpanList<T> high = spansOf(*one, makeRay<T>(Vec3d(-5, 0, 2), Vec3d(1, 0, 0)));
  REQUIRE(high.size() == 1);
  double r = std::sqrt(2.0);
  // grad = (2x, 2y, -2z/c^2) = (2x, 0, -1) at z = 2
  expectSpan(high[0], 5 - r, 5 + r, Vec3d(-2 * r, 0, -1), Vec3d(2 * r, 0, -1));

  auto two = leafOf<T>(hyperboloid(1, 2, false));
  SpanList<T> axis = spansOf(*two, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(axis.size() == 2);
  expectSpan(axis[0], -kInf, 3, {}, Vec3d(0, 0, 1));
  expectSpan(axis[1], 7, kInf, Vec3d(0, 0, -1), {});
  REQUIRE(spansOf(*two, makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0))).empty());
}

TEMPLATE_TEST_CASE("torus: four crossings through the hole, tube normals", "[shapes]", float, double) {
  using T = TestType;
  QuarticShape s = torus(2, 0.5);
  REQUIRE(s.bounds.hi.x == 2.5);
  REQUIRE(s.bounds.hi.z == 0.5);
  auto leaf = leafOf<T>(s);
  SpanList<T> across = spansOf(*leaf, makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0)));
  REQUIRE(across.size() == 2);
  expectSpan(across[0], 2.5, 3.5, Vec3d(-1, 0, 0), Vec3d(1, 0, 0));
  expectSpan(across[1], 6.5, 7.5, Vec3d(-1, 0, 0), Vec3d(1, 0, 0));
  // Through the tube vertically at x = 2.3: z = +-sqrt(0.25 - 0.09) = +-0.4.
  SpanList<T> tube = spansOf(*leaf, makeRay<T>(Vec3d(2.3, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(tube.size() == 1);
  expectSpan(tube[0], 4.6, 5.4, Vec3d(0.3, 0, -0.4), Vec3d(0.3, 0, 0.4));
  REQUIRE(spansOf(*leaf, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1))).empty());
  REQUIRE_THROWS_AS(torus(2, 0), Error);
}

TEMPLATE_TEST_CASE("capsule equals the points within radius of its segment", "[shapes][csg]", float, double) {
  using T = TestType;
  Mat4d m = glm::translate(Mat4d(1), Vec3d(0.5, -1, 2)) * glm::rotate(Mat4d(1), 0.7, glm::normalize(Vec3d(1, 2, 0.5)));
  const double radius = 0.4, length = 2.0;
  auto capsule = makeCapsule<T>(radius, length, m, 5);
  Vec3d a = Vec3d(m * glm::dvec4(0, 0, 0, 1)), b = Vec3d(m * glm::dvec4(0, 0, length, 1));
  auto inside = [&](const Vec3d& p) {
    double s = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
    return glm::length(p - (a + (b - a) * s)) < radius;
  };
  // The box is tight, not the unbounded box of its rotated parts.
  REQUIRE(capsule->bounds().isFinite());
  REQUIRE(double(glm::length(capsule->bounds().hi - capsule->bounds().lo)) < 2 * (length + 2 * radius));
  std::mt19937 rng(11);
  int hits = 0;
  for (int n = 0; n < 300; ++n) {
    Vec3d target = (a + b) * 0.5 + randomUnit(rng) * 1.2;
    Vec3d o = target + randomUnit(rng) * 6.0;
    Ray<T> ray = makeRay<T>(o, glm::normalize(target - o));
    checkAgainstOracle<T>(*capsule, ray, inside, 0, 12, 300, 1e-3);
    Hit<T> hit;
    if (capsule->firstHit(ray, T(0), T(100), hit)) {
      ++hits;
      Vec3d p = Vec3d(ray.origin) + Vec3d(ray.direction) * double(hit.t);
      double s = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
      Vec3d radial = p - (a + (b - a) * s);
      REQUIRE(glm::length(radial) == Approx(radius).epsilon(1e-3));
      REQUIRE(glm::dot(Vec3d(hit.normal), glm::normalize(radial)) > 0.999);
      REQUIRE(hit.material == 5u);
    }
  }
  REQUIRE(hits > 50);
  REQUIRE_THROWS_AS(makeCapsule<T>(0, 1, Mat4d(1), 0), Error);
  REQUIRE_THROWS_AS(makeCapsule<T>(1, -1, Mat4d(1), 0), Error);
  REQUIRE(makeCapsule<T>(1, 0, Mat4d(1), 0)->bounds().isFinite());
}

// A strip of parallel rays sweeping across a silhouette. The hit/miss
// pattern must be one contiguous run (no isolated misses = speckles) that
// matches the analytic edge, and the hit distance must match the analytic
// one ray by ray.
template <typename T>
void sweep(const Primitive<T>& p, int count, const std::function<Ray<T>(int)>& rayAt,
           const std::function<double(int)>& expectedT, double tTol) {
  int transitions = 0;
  bool previous = false;
  for (int n = 0; n < count; ++n) {
    Ray<T> ray = rayAt(n);
    Hit<T> hit;
    bool got = p.firstHit(ray, T(0), std::numeric_limits<T>::infinity(), hit);
    double want = expectedT(n);  // NaN: must miss; -1: too close to the edge to say
    INFO("ray " << n << " of " << count << " expected t " << want << " got " << (got ? double(hit.t) : -1.0));
    if (want >= 0) {
      REQUIRE(got);
      REQUIRE(double(hit.t) == Approx(want).margin(tTol));
    } else if (std::isnan(want)) {
      REQUIRE_FALSE(got);
    }
    REQUIRE(got == p.anyHit(ray, T(0), std::numeric_limits<T>::infinity()));
    if (n > 0 && got != previous) ++transitions;
    previous = got;
  }
  REQUIRE(transitions <= 2);
}

TEMPLATE_TEST_CASE("near-tangent rays on a sphere of radius 1e6 give no speckles", "[shapes][silhouette]", float,
                   double) {
  using T = TestType;
  const double r = 1e6;
  auto leaf = leafOf<T>(sphere(r));
  // Rays along +x from x = -3e6 at heights h from 0.98r to 1.02r.
  const int count = 4001;
  const double edgeBand = std::is_same_v<T, float> ? 1.0 : 1e-3;  // 1 unit of 1e6 in float
  auto height = [&](int n) { return r * (0.98 + 0.04 * n / (count - 1)); };
  sweep<T>(
      *leaf, count, [&](int n) { return makeRay<T>(Vec3d(-3 * r, height(n), 0), Vec3d(1, 0, 0)); },
      [&](int n) {
        double h = height(n);
        if (std::abs(h - r) < edgeBand) return -1.0;
        if (h > r) return std::numeric_limits<double>::quiet_NaN();
        return 3 * r - std::sqrt((r - h) * (r + h));
      },
      std::is_same_v<T, float> ? 200.0 : 1e-3);
}

TEMPLATE_TEST_CASE("near-tangent rays on a torus give no speckles", "[shapes][silhouette]", float, double) {
  using T = TestType;
  const double R = 2, rt = 0.5;
  auto leaf = leafOf<T>(torus(R, rt));
  const int count = 2001;
  const double edgeBand = std::is_same_v<T, float> ? 2e-3 : 1e-6;
  const double tTol = std::is_same_v<T, float> ? 3e-2 : 1e-4;
  // Horizontal rays along +x at heights z sweeping over the top of the tube.
  auto z = [&](int n) { return rt * (0.9 + 0.2 * n / (count - 1)); };
  sweep<T>(
      *leaf, count, [&](int n) { return makeRay<T>(Vec3d(-5, 0, z(n)), Vec3d(1, 0, 0)); },
      [&](int n) {
        double h = z(n);
        if (std::abs(h - rt) < edgeBand) return -1.0;
        if (h > rt) return std::numeric_limits<double>::quiet_NaN();
        return 5 - (R + std::sqrt(rt * rt - h * h));
      },
      tTol);
  // Vertical rays sweeping across the inner silhouette (the hole's edge).
  auto x = [&](int n) { return (R - rt) * (0.98 + 0.04 * n / (count - 1)); };
  sweep<T>(
      *leaf, count, [&](int n) { return makeRay<T>(Vec3d(x(n), 0, -5), Vec3d(0, 0, 1)); },
      [&](int n) {
        double d = x(n) - R;  // offset from the tube's centre-line
        if (std::abs(std::abs(d) - rt) < edgeBand) return -1.0;
        if (std::abs(d) > rt) return std::numeric_limits<double>::quiet_NaN();
        return 5 - std::sqrt(rt * rt - d * d);
      },
      tTol);
  // Oblique rays grazing the outer rim: no analytic form, but a contiguous
  // run of hits whose distance varies smoothly.
  std::vector<double> ts;
  bool previous = false;
  int transitions = 0;
  for (int n = 0; n < count; ++n) {
    double y = (R + rt) * (0.9 + 0.2 * n / (count - 1));
    Ray<T> ray = makeRay<T>(Vec3d(-5, y, -1), glm::normalize(Vec3d(1, 0, 0.2)));
    Hit<T> hit;
    bool got = leaf->firstHit(ray, T(0), T(100), hit);
    if (n > 0 && got != previous) ++transitions;
    previous = got;
    if (got) ts.push_back(double(hit.t));
  }
  REQUIRE(transitions <= 2);
  REQUIRE(ts.size() > 100);
  for (std::size_t n = 1; n + 1 < ts.size(); ++n) {
    // No outlier: each distance lies near the mean of its neighbours.
    INFO("hit " << n << " t " << ts[n] << " neighbours " << ts[n - 1] << ", " << ts[n + 1]);
    REQUIRE(std::abs(ts[n] - 0.5 * (ts[n - 1] + ts[n + 1])) < 0.05);
  }
}

TEMPLATE_TEST_CASE("a small sphere seen from 1e5 radii away keeps a clean silhouette", "[shapes][silhouette]", float,
                   double) {
  using T = TestType;
  // Substituting the ray at its far origin would make the constant term
  // 1e10 - 1, which float cannot hold; rays are re-based near the object.
  auto leaf = leafOf<T>(sphere(1.0), glm::translate(Mat4d(1), Vec3d(0, 0, 3)));
  const int count = 2001;
  const double distance = 1e5, edgeBand = std::is_same_v<T, float> ? 2e-3 : 1e-7;
  auto height = [&](int n) { return -1.1 + 2.2 * n / (count - 1); };
  sweep<T>(
      *leaf, count, [&](int n) { return makeRay<T>(Vec3d(-distance, height(n), 3), Vec3d(1, 0, 0)); },
      [&](int n) {
        double h = height(n);
        if (std::abs(std::abs(h) - 1) < edgeBand) return -1.0;
        if (std::abs(h) > 1) return std::numeric_limits<double>::quiet_NaN();
        return distance - std::sqrt(1 - h * h);
      },
      std::is_same_v<T, float> ? 2e-2 : 1e-6);
}
