// Instance nodes (render/scene/instance_node.hpp): one object-space polyline shared
// by a placement must answer every query as the world-space copy of it does
// (spans, first hit, first enter, any hit; t and normals to rounding), under a
// rigid placement and under a non-uniform scale (normals by the inverse
// transpose); its box must hold every hit and be tighter than the object's
// box turned; a bad transform is a located error, not a crash.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include "geometry_checks.hpp"
#include "render/scene/instance_node.hpp"
#include "render/scene/builtin_leaves.hpp"
#include "render/shapes/polyline_shape.hpp"
#include "render/scene/scene.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

const std::vector<Vec3d> kHair{{0, 0, 0}, {0.01, 0.005, 0.05}, {0.03, 0.01, 0.1}, {0.06, 0.01, 0.15}};
constexpr double kRadius = 0.01;

Mat4d placement(bool scaled) {
  Mat4d m = glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.9)) *
            glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 2, 3)));
  if (scaled) m = m * glm::scale(Mat4d(1.0), Vec3d(1.0, 2.5, 0.8));
  return m;
}

template <typename T>
bool contains(const Bounds<T>& b, const Vec3<T>& p) {
  return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

template <typename T>
void checkSameHit(const Hit<T>& a, const Hit<T>& b, double tol) {
  CHECK(double(a.t) == Approx(double(b.t)).margin(tol));
  CHECK(glm::dot(Vec3d(a.normal), Vec3d(b.normal)) > 1.0 - 100 * tol);
  CHECK(a.material == b.material);
}

template <typename T>
void compareWithCopy(bool scaled) {
  const double tol = sizeof(T) == 4 ? 2e-5 : 1e-10;
  const Mat4d toWorld = placement(scaled);
  const PrimitivePtr<T> copy = makePolyline<T>(kHair, kRadius, toWorld, 3);
  const SharedPrimitive<T> object(makePolyline<T>(kHair, kRadius, Mat4d(1.0), 3));
  NodeDesc desc = NodeDesc::makeLeaf(makePolylineLeafDesc(kHair, kRadius), "test");
  const PrimitivePtr<T> instance = makeInstance<T>(object, toWorld, placedBounds(desc, toWorld));

  std::mt19937 rng(13);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  const Bounds<T>& box = copy->bounds();
  const Vec3d centre = (Vec3d(box.lo) + Vec3d(box.hi)) * 0.5;
  int hits = 0, grazes = 0;
  const int rays = 3000;
  for (int n = 0; n < rays; ++n) {
    const Vec3d origin = centre - randomUnit(rng) * 2.0;
    const Vec3d aim = centre + Vec3d(jitter(rng), jitter(rng), 2 * jitter(rng));
    const Ray<T> ray = makeRay<T>(origin, aim - origin);
    SpanList<T> a = spansOf(*copy, ray), b = spansOf(*instance, ray);
    if (a.size() != b.size()) {
      ++grazes;  // a tangent line solved in two spaces: only where the chord is tiny
      const SpanList<T>& more = a.size() > b.size() ? a : b;
      double shortest = 1e9;
      for (const Span<T>& s : more) shortest = std::min(shortest, double(s.leave.t - s.enter.t));
      REQUIRE(shortest * glm::length(aim - origin) < 1e-3);
      continue;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      checkSameHit(a[i].enter, b[i].enter, tol);
      checkSameHit(a[i].leave, b[i].leave, tol);
      for (const Vec3d& p : {Vec3d(ray.at(a[i].enter.t)), Vec3d(ray.at(a[i].leave.t))})
        CHECK(contains(instance->bounds(), Vec3<T>(p)));
    }
    Hit<T> ha, hb;
    const bool fa = copy->firstHit(ray, T(0), T(10), ha), fb = instance->firstHit(ray, T(0), T(10), hb);
    REQUIRE(fa == fb);
    if (fa) {
      ++hits;
      checkSameHit(ha, hb, tol);
    }
    bool insideA = false, insideB = false;
    const bool ea = copy->firstEnter(ray, T(0), T(10), ha, insideA);
    const bool eb = instance->firstEnter(ray, T(0), T(10), hb, insideB);
    REQUIRE(ea == eb);
    CHECK(insideA == insideB);
    if (ea) checkSameHit(ha, hb, tol);
    CHECK(copy->anyHit(ray, T(0), T(10)) == instance->anyHit(ray, T(0), T(10)));
  }
  INFO(hits << " hits, " << grazes << " grazes of " << rays);
  CHECK(hits > rays / 10);  // aimed at the hair: hundreds of hits are compared, not only misses
  CHECK(grazes <= rays / 200);
}

double volume(const Bounds<double>& b) { return (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * (b.hi.z - b.lo.z); }

}  // namespace

TEMPLATE_TEST_CASE("instance: a shared object-space polyline answers like its world-space copy", "", float, double) {
  SECTION("rigid placement") { compareWithCopy<TestType>(false); }
  SECTION("non-uniform scale: normals by the inverse transpose") { compareWithCopy<TestType>(true); }
}

TEST_CASE("instance: the placed box is the balls' box, tighter than the object box turned") {
  const Mat4d toWorld = placement(false);
  NodeDesc desc = NodeDesc::makeLeaf(makePolylineLeafDesc(kHair, kRadius), "test");
  const Bounds<double> placed = placedBounds(desc, toWorld);
  const Bounds<double> turned = transformBounds(polylineBounds(kHair, kRadius), toWorld);
  CHECK(volume(placed) < 0.8 * volume(turned));
  // Every ball's extreme points lie in it (a rigid map keeps the radius).
  for (const Vec3d& p : kHair)
    for (int a = 0; a < 3; ++a)
      for (double s : {-1.0, 1.0}) {
        Vec3d e = transformPoint(toWorld, p);
        e[a] += s * kRadius * (1 - 1e-12);
        CHECK(contains(placed, e));
      }
  // Under a difference only the first operand counts.
  NodeDesc far = NodeDesc::makeLeaf(makePolylineLeafDesc({{5, 5, 5}, {6, 6, 6}}, kRadius), "test");
  NodeDesc minus = NodeDesc::makeOperation(NodeDesc::Kind::Difference, {desc, far}, "test");
  CHECK(volume(placedBounds(minus, toWorld)) == Approx(volume(placed)));
}

TEST_CASE("instance: a non-finite placement is an input error") {
  const SharedPrimitive<double> object(makePolyline<double>(kHair, kRadius, Mat4d(1.0), 0));
  Mat4d bad(1.0);
  bad[3][0] = std::numeric_limits<double>::quiet_NaN();
  try {
    makeInstance<double>(object, bad, object->bounds());
    FAIL("accepted");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK(std::string(e.what()).find("instance transform") != std::string::npos);
  }
}
