// CSG nodes against the set definitions (union / intersection / difference of
// point sets), with normals, materials, nesting, rays starting inside,
// tangent rays, coincident surfaces, and any-hit agreeing with first-hit.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "geometry_checks.hpp"
#include "render/shapes/csg.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "render/shapes/span_ops.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <typename T>
PrimitivePtr<T> ball(const Vec3d& c, double r, MaterialId m = 0) {
  QuarticShape s = sphere(r);
  return makeQuarticLeaf<T>(s.f, s.bounds, glm::translate(Mat4d(1), c), m);
}

template <typename T>
PrimitivePtr<T> plane(const Vec3d& n, double offset, MaterialId m = 0) {
  QuarticShape s = halfSpace(n, offset);
  return makeQuarticLeaf<T>(s.f, s.bounds, Mat4d(1), m);
}

// An axis-aligned box as the intersection of six half-spaces.
template <typename T>
PrimitivePtr<T> box(const Vec3d& lo, const Vec3d& hi, MaterialId m = 0) {
  std::vector<PrimitivePtr<T>> sides;
  for (int a = 0; a < 3; ++a) {
    Vec3d n(0);
    n[a] = 1;
    sides.push_back(plane<T>(n, hi[a], m));
    sides.push_back(plane<T>(-n, -lo[a], m));
  }
  return makeCsgNode<T>(CsgOp::Intersection, std::move(sides));
}

template <typename... P>
std::vector<PrimitivePtr<double>> list(P&&... p) {
  std::vector<PrimitivePtr<double>> v;
  (v.push_back(std::forward<P>(p)), ...);
  return v;
}

bool inBall(const Vec3d& p, const Vec3d& c, double r) { return glm::length(p - c) < r; }

// Random rays through the region around the origin; spans checked against the oracle,
// and anyHit/firstHit checked for agreement on segments starting outside.
template <typename T>
void checkRandomRays(const Primitive<T>& solid, const Inside& inside, unsigned seed, int rays = 150) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int n = 0; n < rays; ++n) {
    Vec3d target = randomUnit(rng) * 2.0 * u(rng);
    Vec3d o = target + randomUnit(rng) * 7.0;
    Ray<T> ray = makeRay<T>(o, glm::normalize(target - o));
    checkAgainstOracle<T>(solid, ray, inside, -3, 17, 400, 1e-4);
    Hit<T> hit;
    for (double tmax : {3.0, 6.0, 9.0, 100.0}) {
      bool first = solid.firstHit(ray, T(0), T(tmax), hit);
      REQUIRE(first == solid.anyHit(ray, T(0), T(tmax)));
      // firstHit is the first crossing in the merged span list.
      SpanList<T> all = spansOf(solid, ray, T(0), T(tmax));
      Hit<T> expected;
      bool any = firstCrossing(all, T(0), T(tmax), expected);
      REQUIRE(any == first);
      if (first) {
        REQUIRE(double(hit.t) == Approx(double(expected.t)));
        REQUIRE(hit.material == expected.material);
      }
    }
  }
}

}  // namespace

TEST_CASE("span merging rules: union coalesces, intersection clips, difference flips", "[csg]") {
  auto span = [](double a, double b, MaterialId m) {
    return Span<double>{{a, Vec3d(-1, 0, 0), m}, {b, Vec3d(1, 0, 0), m}};
  };
  SpanList<double> u;
  for (auto s : {span(4, 6, 1), span(0, 2, 0), span(2, 3, 2), span(5, 9, 3)}) u.push_back(s);
  coalesceSpans(u);
  REQUIRE(u.size() == 2);
  REQUIRE((u[0].enter.t == 0 && u[0].leave.t == 3 && u[0].leave.material == 2));  // touching spans join
  REQUIRE((u[1].enter.t == 4 && u[1].leave.t == 9 && u[1].leave.material == 3));

  SpanList<double> a, b, out;
  a.push_back(span(0, 10, 0));
  b.push_back(span(2, 3, 1));
  b.push_back(span(8, 12, 2));
  subtractSpans(a, b, out);
  REQUIRE(out.size() == 2);
  REQUIRE((out[0].enter.t == 0 && out[0].leave.t == 2));
  REQUIRE(out[0].leave.normal == Vec3d(1, 0, 0));  // flipped enter of b
  REQUIRE(out[0].leave.material == 1u);
  REQUIRE((out[1].enter.t == 3 && out[1].leave.t == 8));
  REQUIRE(out[1].enter.normal == Vec3d(-1, 0, 0));  // flipped leave of b
  out.clear();
  intersectSpans(a, b, out);
  REQUIRE(out.size() == 2);
  REQUIRE((out[1].enter.t == 8 && out[1].leave.t == 10 && out[1].enter.material == 2 && out[1].leave.material == 0));
  out.clear();
  subtractSpans(a, a, out);
  REQUIRE(out.empty());
}

TEMPLATE_TEST_CASE("union, intersection, difference of spheres match their point sets", "[csg]", float, double) {
  using T = TestType;
  const Vec3d c1(-0.6, 0, 0), c2(0.6, 0.2, 0), c3(0, -0.3, 0.5);
  auto make = [&](CsgOp op) {
    std::vector<PrimitivePtr<T>> v;
    v.push_back(ball<T>(c1, 1.0, 1));
    v.push_back(ball<T>(c2, 0.9, 2));
    v.push_back(ball<T>(c3, 0.7, 3));
    return makeCsgNode<T>(op, std::move(v));
  };
  auto in1 = [&](const Vec3d& p) { return inBall(p, c1, 1.0); };
  auto in2 = [&](const Vec3d& p) { return inBall(p, c2, 0.9); };
  auto in3 = [&](const Vec3d& p) { return inBall(p, c3, 0.7); };
  checkRandomRays<T>(*make(CsgOp::Union), [&](const Vec3d& p) { return in1(p) || in2(p) || in3(p); }, 1);
  checkRandomRays<T>(*make(CsgOp::Intersection), [&](const Vec3d& p) { return in1(p) && in2(p) && in3(p); }, 2);
  checkRandomRays<T>(*make(CsgOp::Difference), [&](const Vec3d& p) { return in1(p) && !in2(p) && !in3(p); }, 3);
}

TEMPLATE_TEST_CASE("nested CSG with half-spaces matches its point set", "[csg]", float, double) {
  using T = TestType;
  // (box - ball) U (ball2 n z < 0.3): a hollowed cube next to a cut ball.
  std::vector<PrimitivePtr<T>> diff;
  diff.push_back(box<T>(Vec3d(-1.5, -1, -1), Vec3d(0.5, 1, 1), 1));
  diff.push_back(ball<T>(Vec3d(-0.5, 0, 0.2), 1.1, 2));
  std::vector<PrimitivePtr<T>> cut;
  cut.push_back(ball<T>(Vec3d(1, 0.5, 0), 0.9, 3));
  cut.push_back(plane<T>(Vec3d(0, 0, 1), 0.3, 4));
  std::vector<PrimitivePtr<T>> top;
  top.push_back(makeCsgNode<T>(CsgOp::Difference, std::move(diff)));
  top.push_back(makeCsgNode<T>(CsgOp::Intersection, std::move(cut)));
  auto solid = makeCsgNode<T>(CsgOp::Union, std::move(top));
  auto inside = [](const Vec3d& p) {
    bool inBox = p.x > -1.5 && p.x < 0.5 && std::abs(p.y) < 1 && std::abs(p.z) < 1;
    return (inBox && !inBall(p, Vec3d(-0.5, 0, 0.2), 1.1)) || (inBall(p, Vec3d(1, 0.5, 0), 0.9) && p.z < 0.3);
  };
  checkRandomRays<T>(*solid, inside, 4, 250);
}

TEMPLATE_TEST_CASE("difference: cavity normals point out of the result, materials follow the surface", "[csg]",
                   float, double) {
  using T = TestType;
  std::vector<PrimitivePtr<T>> v;
  v.push_back(ball<T>(Vec3d(0), 2, 7));
  v.push_back(ball<T>(Vec3d(0), 1, 9));
  auto shell = makeCsgNode<T>(CsgOp::Difference, std::move(v));
  SpanList<T> s = spansOf(*shell, makeRay<T>(Vec3d(0, 0, -5), Vec3d(0, 0, 1)));
  REQUIRE(s.size() == 2);
  REQUIRE(double(s[0].enter.t) == Approx(3));
  REQUIRE(double(s[0].enter.normal.z) == Approx(-1));
  REQUIRE(s[0].enter.material == 7u);
  REQUIRE(double(s[0].leave.t) == Approx(4));
  REQUIRE(double(s[0].leave.normal.z) == Approx(1));  // into the cavity = out of the shell
  REQUIRE(s[0].leave.material == 9u);
  REQUIRE(double(s[1].enter.t) == Approx(6));
  REQUIRE(double(s[1].enter.normal.z) == Approx(-1));
  REQUIRE(double(s[1].leave.t) == Approx(7));
  // From the centre (inside the cavity), the first surface is the cavity wall.
  Hit<T> hit;
  REQUIRE(shell->firstHit(makeRay<T>(Vec3d(0), Vec3d(0, 0, 1)), T(0), T(10), hit));
  REQUIRE(double(hit.t) == Approx(1));
  REQUIRE(double(hit.normal.z) == Approx(-1));  // faces the ray coming from the cavity
  REQUIRE(hit.material == 9u);
  // The difference's box is the first child's.
  REQUIRE(double(shell->bounds().hi.x) == Approx(2));
}

TEMPLATE_TEST_CASE("union first hit from a ray starting inside a child", "[csg]", float, double) {
  using T = TestType;
  std::vector<PrimitivePtr<T>> v;
  v.push_back(ball<T>(Vec3d(0), 1, 1));
  v.push_back(ball<T>(Vec3d(1.5, 0, 0), 1, 2));
  v.push_back(ball<T>(Vec3d(6, 0, 0), 1, 3));
  auto u = makeCsgNode<T>(CsgOp::Union, std::move(v));
  // Starts inside ball 1; ball 2's entry at x = 0.5 is inside ball 1, not a surface.
  Hit<T> hit;
  Ray<T> ray = makeRay<T>(Vec3d(0), Vec3d(1, 0, 0));
  REQUIRE(u->firstHit(ray, T(0), T(100), hit));
  REQUIRE(double(hit.t) == Approx(2.5));
  REQUIRE(hit.material == 2u);
  REQUIRE(double(hit.normal.x) == Approx(1));
  // Starting outside: the nearest sphere in front.
  REQUIRE(u->firstHit(makeRay<T>(Vec3d(10, 0, 0), Vec3d(-1, 0, 0)), T(0), T(100), hit));
  REQUIRE(double(hit.t) == Approx(3));
  REQUIRE(hit.material == 3u);
  // A segment wholly inside one child has no crossing.
  REQUIRE_FALSE(u->firstHit(ray, T(0), T(0.4), hit));
}

TEMPLATE_TEST_CASE("tangent rays and touching solids", "[csg]", float, double) {
  using T = TestType;
  // Two unit balls touching at the origin.
  std::vector<PrimitivePtr<T>> v;
  v.push_back(ball<T>(Vec3d(-1, 0, 0), 1, 1));
  v.push_back(ball<T>(Vec3d(1, 0, 0), 1, 2));
  auto u = makeCsgNode<T>(CsgOp::Union, std::move(v));
  // Along the line of centres the touching spans coalesce into one.
  SpanList<T> s = spansOf(*u, makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0)));
  REQUIRE(s.size() == 1);
  REQUIRE(double(s[0].enter.t) == Approx(3));
  REQUIRE(double(s[0].leave.t) == Approx(7));
  // Tangent to both balls at their top: nothing (or vanishing slivers) is hit.
  SpanList<T> top = spansOf(*u, makeRay<T>(Vec3d(-5, 1, 0), Vec3d(1, 0, 0)));
  for (const Span<T>& sp : top) REQUIRE(double(sp.leave.t - sp.enter.t) < 1e-2);
  // Intersection of the touching balls is empty (they share only a point).
  std::vector<PrimitivePtr<T>> w;
  w.push_back(ball<T>(Vec3d(-1, 0, 0), 1));
  w.push_back(ball<T>(Vec3d(1, 0, 0), 1));
  auto i = makeCsgNode<T>(CsgOp::Intersection, std::move(w));
  REQUIRE(spansOf(*i, makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0))).empty());
  REQUIRE_FALSE(i->anyHit(makeRay<T>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0)), T(0), T(100)));
}

TEMPLATE_TEST_CASE("coincident surfaces: shared faces vanish, A - A is empty, A n A is A", "[csg]", float, double) {
  using T = TestType;
  // Two boxes sharing the face x = 0 form one box: a ray along x sees one span.
  std::vector<PrimitivePtr<T>> v;
  v.push_back(box<T>(Vec3d(-1, -1, -1), Vec3d(0, 1, 1), 1));
  v.push_back(box<T>(Vec3d(0, -1, -1), Vec3d(1, 1, 1), 2));
  auto joined = makeCsgNode<T>(CsgOp::Union, std::move(v));
  Ray<T> ray = makeRay<T>(Vec3d(-5, 0.1, 0.2), Vec3d(1, 0, 0));
  SpanList<T> s = spansOf(*joined, ray);
  REQUIRE(s.size() == 1);
  REQUIRE(double(s[0].enter.t) == Approx(4));
  REQUIRE(double(s[0].leave.t) == Approx(6));
  REQUIRE(s[0].leave.material == 2u);

  std::vector<PrimitivePtr<T>> same;
  same.push_back(ball<T>(Vec3d(0.3, 0, 0), 1.5));
  same.push_back(ball<T>(Vec3d(0.3, 0, 0), 1.5));
  auto nothing = makeCsgNode<T>(CsgOp::Difference, std::move(same));
  REQUIRE(spansOf(*nothing, ray).empty());

  std::vector<PrimitivePtr<T>> twice;
  twice.push_back(ball<T>(Vec3d(0.3, 0, 0), 1.5, 4));
  twice.push_back(ball<T>(Vec3d(0.3, 0, 0), 1.5, 4));
  auto once = makeCsgNode<T>(CsgOp::Intersection, std::move(twice));
  SpanList<T> o = spansOf(*once, ray);
  REQUIRE(o.size() == 1);
  REQUIRE(double(o[0].leave.t - o[0].enter.t) == Approx(2 * std::sqrt(1.5 * 1.5 - 0.05)).epsilon(1e-4));

  // Box minus a box sharing its +x face: the face is cut away cleanly.
  std::vector<PrimitivePtr<T>> cut;
  cut.push_back(box<T>(Vec3d(-1, -1, -1), Vec3d(1, 1, 1), 1));
  cut.push_back(box<T>(Vec3d(0, -2, -2), Vec3d(1, 2, 2), 2));
  auto half = makeCsgNode<T>(CsgOp::Difference, std::move(cut));
  SpanList<T> h = spansOf(*half, ray);
  REQUIRE(h.size() == 1);
  REQUIRE(double(h[0].leave.t) == Approx(5));
  REQUIRE(double(h[0].leave.normal.x) == Approx(1));
}

TEMPLATE_TEST_CASE("boxes prune: intersection box is the overlap of the children's", "[csg]", float, double) {
  using T = TestType;
  std::vector<PrimitivePtr<T>> v;
  v.push_back(ball<T>(Vec3d(-1, 0, 0), 1.5));
  v.push_back(ball<T>(Vec3d(1, 0, 0), 1.5));
  auto lens = makeCsgNode<T>(CsgOp::Intersection, std::move(v));
  REQUIRE(double(lens->bounds().lo.x) == Approx(-0.5).margin(1e-5));
  REQUIRE(double(lens->bounds().hi.x) == Approx(0.5).margin(1e-5));
  std::vector<PrimitivePtr<T>> w;
  w.push_back(ball<T>(Vec3d(-1, 0, 0), 1.5));
  w.push_back(ball<T>(Vec3d(4, 0, 0), 1.5));
  auto both = makeCsgNode<T>(CsgOp::Union, std::move(w));
  REQUIRE(double(both->bounds().hi.x) == Approx(5.5).margin(1e-5));
  // n-ary intersection of half-spaces: a unit cube.
  auto cube = box<T>(Vec3d(0), Vec3d(1));
  REQUIRE(cube->bounds().isFinite());
  checkRandomRays<T>(*cube, [](const Vec3d& p) { return glm::all(glm::greaterThan(p, Vec3d(0))) && glm::all(glm::lessThan(p, Vec3d(1))); },
                     5, 100);
}

TEST_CASE("CSG nodes reject unusable children", "[csg]") {
  REQUIRE_THROWS_AS(makeCsgNode<double>(CsgOp::Union, {}), Error);
  std::vector<PrimitivePtr<double>> v;
  v.push_back(nullptr);
  REQUIRE_THROWS_AS(makeCsgNode<double>(CsgOp::Intersection, std::move(v)), Error);
  // A single child behaves like the child.
  auto one = makeCsgNode<double>(CsgOp::Difference, list(ball<double>(Vec3d(0), 1)));
  REQUIRE(spansOf(*one, makeRay<double>(Vec3d(-5, 0, 0), Vec3d(1, 0, 0))).size() == 1);
  (void)kInf;
}

// A union's firstHit answers from its children's first enters (no span lists)
// and falls back to the exact spans when the ray starts inside a child. On a
// union of unions (as a scene's root over a lattice_scatter), with ray origins
// inside and outside the balls, it must give what the merged spans give.
TEMPLATE_TEST_CASE("nested unions: firstHit equals the first crossing of the merged spans", "[csg]", float, double) {
  using T = TestType;
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> coord(-2.0, 2.0), radius(0.2, 0.6);
  std::vector<PrimitivePtr<T>> groups;
  MaterialId material = 0;
  for (int g = 0; g < 3; ++g) {
    std::vector<PrimitivePtr<T>> balls;
    for (int n = 0; n < 12; ++n) balls.push_back(ball<T>(Vec3d(coord(rng), coord(rng), coord(rng)), radius(rng), material++));
    groups.push_back(makeCsgNode<T>(CsgOp::Union, std::move(balls)));
  }
  groups.push_back(plane<T>(Vec3d(0, 1, 0), -2.5, material++));  // an unbounded child, as a floor
  auto root = makeCsgNode<T>(CsgOp::Union, std::move(groups));
  int hits = 0, startsInside = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec3d o(coord(rng), coord(rng), coord(rng));
    const Ray<T> ray = makeRay<T>(o, randomUnit(rng));
    SpanList<T> all = spansOf(*root, ray);
    if (!all.empty() && double(all[0].enter.t) <= 0.0 && double(all[0].leave.t) > 0.0) ++startsInside;
    Hit<T> expected, got;
    const bool want = firstCrossing(all, T(0), std::numeric_limits<T>::infinity(), expected);
    REQUIRE(root->firstHit(ray, T(0), std::numeric_limits<T>::infinity(), got) == want);
    if (!want) continue;
    ++hits;
    CHECK(got.t == expected.t);
    CHECK(got.material == expected.material);
    CHECK(glm::dot(Vec3d(got.normal), Vec3d(expected.normal)) > 0.9999);
  }
  CHECK(hits > 1000);
  CHECK(startsInside > 100);  // the fallback path was taken, not only the fast one
}
