// Quartic polynomials (eq. 3.1) and the quartic leaf: exact ray substitution,
// spans from the sign of f, normals, transforms kept at the leaf.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <set>

#include "geometry_checks.hpp"
#include "render/shapes/quartic.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

QuarticPolynomial randomQuartic(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  QuarticPolynomial f;
  for (double& c : f.a) c = u(rng);
  return f;
}

}  // namespace

TEST_CASE("quartic index covers the 35 monomials of eq. 3.1 once each", "[quartic]") {
  std::set<int> seen;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j)
      for (int k = 0; i + j + k <= 4; ++k) {
        int idx = QuarticPolynomial::index(i, j, k);
        REQUIRE(idx >= 0);
        REQUIRE(idx < 35);
        REQUIRE(seen.insert(idx).second);
        REQUIRE(QuarticPolynomial::exponents(idx) == std::array<int, 3>{i, j, k});
      }
  REQUIRE(seen.size() == 35);
  REQUIRE(QuarticPolynomial::index(0, 0, 0) == 0);
  REQUIRE_THROWS_AS(QuarticPolynomial::index(3, 1, 1), Error);
  REQUIRE_THROWS_AS(QuarticPolynomial::index(-1, 0, 0), Error);
  REQUIRE_THROWS_AS(QuarticPolynomial::exponents(35), Error);
}

TEST_CASE("quartic eval and gradient agree with the monomials and finite differences", "[quartic]") {
  QuarticPolynomial f;
  f.addTerm(2, 1, 2, 0).addTerm(-3, 0, 0, 4).addTerm(0.5, 0, 0, 0).addTerm(1, 1, 1, 1);
  Vec3d p(0.3, -1.2, 0.7);
  double expected = 2 * p.x * p.y * p.y - 3 * std::pow(p.z, 4) + 0.5 + p.x * p.y * p.z;
  REQUIRE(f.eval(p) == Approx(expected));
  Vec3d g = f.gradient(p);
  REQUIRE(g.x == Approx(2 * p.y * p.y + p.y * p.z));
  REQUIRE(g.y == Approx(4 * p.x * p.y + p.x * p.z));
  REQUIRE(g.z == Approx(-12 * std::pow(p.z, 3) + p.x * p.y));
  REQUIRE(f.degree() == 4);

  std::mt19937 rng(7);
  QuarticPolynomial r = randomQuartic(rng);
  const double h = 1e-6;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3d e(0);
    e[axis] = h;
    double numeric = (r.eval(p + e) - r.eval(p - e)) / (2 * h);
    REQUIRE(r.gradient(p)[axis] == Approx(numeric).epsilon(1e-6));
  }
}

TEST_CASE("quartic arithmetic builds polynomials and refuses degree > 4", "[quartic]") {
  using P = QuarticPolynomial;
  P diff = (P::x() + P::y()) * (P::x() - P::y());
  REQUIRE(diff.coefficient(2, 0, 0) == 1);
  REQUIRE(diff.coefficient(0, 2, 0) == -1);
  REQUIRE(diff.coefficient(1, 1, 0) == 0);
  P sq = diff * diff;
  REQUIRE(sq.degree() == 4);
  REQUIRE(sq.coefficient(2, 2, 0) == -2);
  REQUIRE_THROWS_AS(sq * P::z(), Error);
  REQUIRE((-P::constant(3)).coefficient(0, 0, 0) == -3);
  REQUIRE((2.0 * P::z()).coefficient(0, 0, 1) == 2);
  REQUIRE(P{}.degree() == -1);
}

TEMPLATE_TEST_CASE("ray substitution is exact: span ends lie on the surface and signs match f", "[quartic]", float,
                   double) {
  using T = TestType;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  // Accuracy of the residual test relative to the scalar's precision.
  const double tol = std::is_same_v<T, float> ? 2e-3 : 1e-8;
  int ends = 0;
  for (int shape = 0; shape < 40; ++shape) {
    QuarticPolynomial f = shape % 2 ? randomQuartic(rng) : torus(1.0 + 0.5 * (u(rng) + 1), 0.4).f;
    auto leaf = makeQuarticLeaf<T>(f, Bounds<double>::infinite(), Mat4d(1.0), 3);
    for (int n = 0; n < 25; ++n) {
      Vec3d o(3 * u(rng), 3 * u(rng), 3 * u(rng));
      Vec3d d = randomUnit(rng) * (0.5 + u(rng) + 1);
      Ray<T> ray = makeRay<T>(o, d);
      SpanList<T> list = spansOf(*leaf, ray);
      checkWellFormed(list);
      for (const Span<T>& s : list) {
        for (const Hit<T>* h : {&s.enter, &s.leave}) {
          if (!std::isfinite(h->t)) continue;
          Vec3d p = o + d * double(h->t);
          // |f| / |grad f| estimates the distance from p to the surface.
          if (glm::length(f.gradient(p)) < 1e-3) continue;  // near a singular point of f
          INFO("shape " << shape << " ray " << n << " t " << h->t);
          REQUIRE(std::abs(f.eval(p)) / glm::length(f.gradient(p)) < tol * (1 + glm::length(p)));
          REQUIRE(h->material == 3u);
          Vec3d g = glm::normalize(f.gradient(p));
          REQUIRE(glm::dot(Vec3d(h->normal), g) > 1 - 100 * tol);
          ++ends;
        }
        // Midpoints of finite spans are inside (f < 0).
        if (std::isfinite(s.enter.t) && std::isfinite(s.leave.t) && s.leave.t - s.enter.t > T(1e-2))
          REQUIRE(f.eval(o + d * (0.5 * (double(s.enter.t) + double(s.leave.t)))) < 0);
      }
      // Points clearly between spans are outside.
      checkAgainstOracle<T>(*leaf, ray, [&](const Vec3d& p) { return f.eval(p) < 0; }, -6, 6, 120,
                            std::is_same_v<T, float> ? 2e-2 : 1e-4);
    }
  }
  REQUIRE(ends > 200);  // the random shapes were actually hit
}

TEMPLATE_TEST_CASE("transforms are kept at the leaf: scaled, rotated, translated sphere = ellipsoid", "[quartic]", float,
                   double) {
  using T = TestType;
  // A unit sphere scaled by (2, 1, 0.5), rotated 30 degrees about z, moved to (1, 2, 3).
  Mat4d m = glm::translate(Mat4d(1), Vec3d(1, 2, 3)) * glm::rotate(Mat4d(1), glm::radians(30.0), Vec3d(0, 0, 1)) *
            glm::scale(Mat4d(1), Vec3d(2, 1, 0.5));
  Mat4d inv = glm::inverse(m);
  QuarticShape s = sphere(1.0);
  auto leaf = makeQuarticLeaf<T>(s.f, s.bounds, m, 0);
  // The world box contains the ellipsoid and is not absurdly large.
  const Bounds<T>& b = leaf->bounds();
  REQUIRE(b.isFinite());
  REQUIRE(double(b.hi.z) == Approx(3.5).epsilon(1e-5));
  REQUIRE(double(b.lo.z) == Approx(2.5).epsilon(1e-5));

  // World-space ellipsoid as an oracle: |inv * p| < 1, outward normal ~ inv^T inv p.
  auto inside = [&](const Vec3d& p) { return glm::length(Vec3d(inv * glm::dvec4(p, 1))) < 1; };
  std::mt19937 rng(3);
  int hits = 0;
  for (int n = 0; n < 200; ++n) {
    Vec3d target = Vec3d(1, 2, 3) + randomUnit(rng) * 1.5;
    Vec3d o = target + randomUnit(rng) * 8.0;
    Vec3d d = (target - o) * 0.25;  // not unit: t must still be world t
    Ray<T> ray = makeRay<T>(o, d);
    checkAgainstOracle<T>(*leaf, ray, inside, 0, 8, 200, 1e-3);
    Hit<T> hit;
    if (leaf->firstHit(ray, T(0), T(100), hit)) {
      ++hits;
      Vec3d p = o + d * double(hit.t);
      Vec3d local = Vec3d(inv * glm::dvec4(p, 1));
      REQUIRE(glm::length(local) == Approx(1).epsilon(std::is_same_v<T, float> ? 1e-4 : 1e-9));
      Vec3d expected = glm::normalize(glm::transpose(glm::dmat3(inv)) * local);
      REQUIRE(glm::dot(Vec3d(hit.normal), expected) > 1 - 1e-5);
      REQUIRE(glm::dot(Vec3d(hit.normal), d) < 0);  // an enter faces the ray
    }
  }
  REQUIRE(hits > 50);
}

TEMPLATE_TEST_CASE("a ray starting inside gets a span that begins before tmin", "[quartic]", float, double) {
  using T = TestType;
  QuarticShape s = sphere(2.0);
  auto leaf = makeQuarticLeaf<T>(s.f, s.bounds, Mat4d(1), 0);
  Ray<T> ray = makeRay<T>(Vec3d(0, 0, 0), Vec3d(1, 0, 0));
  SpanList<T> list = spansOf(*leaf, ray, T(0), T(10));
  REQUIRE(list.size() == 1);
  REQUIRE(double(list[0].enter.t) == Approx(-2));
  REQUIRE(double(list[0].leave.t) == Approx(2));
  Hit<T> hit;
  REQUIRE(leaf->firstHit(ray, T(0), T(10), hit));
  REQUIRE(double(hit.t) == Approx(2));
  REQUIRE(double(hit.normal.x) == Approx(1));
  // Window beyond the sphere: no span overlaps it.
  REQUIRE(spansOf(*leaf, ray, T(3), T(10)).empty());
  REQUIRE_FALSE(leaf->anyHit(ray, T(3), T(10)));
}

TEMPLATE_TEST_CASE("tangent and degenerate rays give no volume and no crash", "[quartic]", float, double) {
  using T = TestType;
  QuarticShape s = sphere(1.0);
  auto leaf = makeQuarticLeaf<T>(s.f, s.bounds, Mat4d(1), 0);
  // Exactly tangent: a double root encloses nothing.
  SpanList<T> tangent = spansOf(*leaf, makeRay<T>(Vec3d(-5, 1, 0), Vec3d(1, 0, 0)));
  for (const Span<T>& sp : tangent) REQUIRE(double(sp.leave.t - sp.enter.t) < 1e-2);
  // Zero direction: no crossing.
  REQUIRE(spansOf(*leaf, makeRay<T>(Vec3d(0, 0, 0), Vec3d(0, 0, 0))).empty());
  // A ray lying in a plane (f identically 0 along it) crosses no volume.
  QuarticShape plane = halfSpace(Vec3d(0, 0, 1), 0);
  auto half = makeQuarticLeaf<T>(plane.f, plane.bounds, Mat4d(1), 0);
  REQUIRE(spansOf(*half, makeRay<T>(Vec3d(0, 0, 0), Vec3d(1, 1, 0))).empty());
  // A ray parallel to the plane below it is inside everywhere.
  SpanList<T> below = spansOf(*half, makeRay<T>(Vec3d(0, 0, -1), Vec3d(1, 1, 0)));
  REQUIRE(below.size() == 1);
  REQUIRE(std::isinf(below[0].enter.t));
  REQUIRE(std::isinf(below[0].leave.t));
}

TEST_CASE("quartic leaves reject unusable transforms and coefficients", "[quartic]") {
  QuarticShape s = sphere(1.0);
  REQUIRE_THROWS_AS(makeQuarticLeaf<double>(s.f, s.bounds, glm::scale(Mat4d(1), Vec3d(1, 0, 1)), 0), Error);
  Mat4d bad(1);
  bad[3][0] = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_AS(makeQuarticLeaf<float>(s.f, s.bounds, bad, 0), Error);
  QuarticPolynomial f = s.f;
  f.a[0] = std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_AS(makeQuarticLeaf<float>(f, s.bounds, Mat4d(1), 0), Error);
  // Fine in double, but float cannot hold the coefficients.
  QuarticShape huge = sphere(1e39);
  REQUIRE_THROWS_AS(makeQuarticLeaf<float>(huge.f, huge.bounds, Mat4d(1), 0), Error);
  REQUIRE(makeQuarticLeaf<double>(huge.f, huge.bounds, Mat4d(1), 0)->bounds().isFinite());
  REQUIRE_THROWS_AS(makeQuarticLeaf<float>(s.f, s.bounds, glm::scale(Mat4d(1), Vec3d(1e-39)), 0), Error);
}

// The leaf substitutes a ray into a quartic of the torus's form (a |p|^4 +
// b (x^2+y^2) + c z^2 + d) by a closed form and skips rays whose line misses
// its object box; any other quartic takes the general expansion. The same
// torus written about the x axis (not of that form) and turned onto it must
// give the same spans to rounding.
TEMPLATE_TEST_CASE("a torus's closed-form substitution crosses where the general expansion does", "[quartic]", float,
                   double) {
  using T = TestType;
  const double R = 1.3, r = 0.4, e = R + r;
  const QuarticShape aboutZ = torus(R, r);
  using P = QuarticPolynomial;
  const P rho2 = P::y() * P::y() + P::z() * P::z();
  const P d = rho2 + P::x() * P::x() + P::constant(R * R - r * r);
  const P aboutX = (d * d - rho2 * (4.0 * R * R)) * (1.0 / (R * R));
  // Object z onto world x: (x, y, z) -> (z, y, -x).
  const Mat4d zToX = glm::rotate(Mat4d(1.0), glm::half_pi<double>(), Vec3d(0, 1, 0));
  auto closed = makeQuarticLeaf<T>(aboutZ.f, aboutZ.bounds, zToX, 1);
  auto general = makeQuarticLeaf<T>(aboutX, Bounds<double>{Vec3d(-r, -e, -e), Vec3d(r, e, e)}, Mat4d(1.0), 1);

  std::mt19937 rng(27);
  std::uniform_real_distribution<double> coordinate(-4.0, 4.0), aim(-2.0, 2.0);
  const double tolerance = std::is_same_v<T, float> ? 2e-3 : 1e-9;
  int crossed = 0, missed = 0, grazing = 0;
  for (int n = 0; n < 4000; ++n) {
    const Vec3d origin(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3d target(aim(rng) * 0.3, aim(rng), aim(rng));
    const Ray<T> ray = makeRay<T>(origin, target - origin);
    const SpanList<T> a = spansOf(*closed, ray), b = spansOf(*general, ray);
    // A ray grazing the tube may touch it in one form and not the other.
    if (a.size() != b.size()) {
      REQUIRE(std::abs(int(a.size()) - int(b.size())) <= 1);
      ++grazing;
      continue;
    }
    for (std::size_t s = 0; s < a.size(); ++s) {
      REQUIRE(static_cast<double>(a[s].enter.t) == Approx(static_cast<double>(b[s].enter.t)).margin(tolerance));
      REQUIRE(static_cast<double>(a[s].leave.t) == Approx(static_cast<double>(b[s].leave.t)).margin(tolerance));
      REQUIRE(static_cast<double>(dot(a[s].enter.normal, b[s].enter.normal)) == Approx(1.0).margin(tolerance));
    }
    (a.empty() ? missed : crossed) += 1;
  }
  REQUIRE(grazing <= 4);
  REQUIRE(crossed > 1000);
  REQUIRE(missed > 500);
}
