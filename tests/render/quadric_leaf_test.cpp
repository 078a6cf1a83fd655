// The closed-form quadric (render/shapes/quadric_leaf.cpp) against the quartic leaf
// it replaces in float and double, for every degree-2 preset (cylinder,
// ellipsoid, cone, paraboloid, hyperboloids of one and two sheets) under a
// rigid placement and a non-uniform scale: 3,000 random rays each, half of
// them starting inside the shape's box, a tenth of them grazing (along the
// tangent plane at a surface point, 0 to 1e-3 off it). Tolerances (tol 2e-4
// in float, 1e-9 in double) are stated at compare() below; grazes among the
// rays not aimed to graze are bounded.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include "geometry_checks.hpp"
#include "foundation/error.hpp"
#include "render/shapes/quadric_leaf.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

struct Compared {
  int agreed = 0, bothMissed = 0, unbounded = 0, grazes = 0;
};

// How far a world point is from the surface, to first order: |f| / |grad f|
// in object space (the placements scale by at most 2.5).
struct Surface {
  const QuarticShape& shape;
  Mat4d worldToObject;
  double distance(const Vec3d& world) const {
    const Vec3d p(worldToObject * glm::dvec4(world, 1.0));
    return std::abs(shape.f.eval(p)) / glm::length(shape.f.gradient(p));
  }
};

// Where the two forms differ in the number of spans, every span one has and
// the other lacks must be a graze: its middle lies within tol / 20 of the
// surface (about what the arithmetic resolves for points a few units out).
// Matched ends must agree across the surface, |dt (n . d)| <= tol (1 + |t|),
// and, where the ray meets the surface at more than a 0.1 cosine, along the
// ray too, |dt| <= tol (1 + |t|), with the same normal to 1e3 tol. A crossing
// beyond 100 units (20 times the region the rays start in) is a ray nearly
// parallel to a ruling or an asymptote, its root conditioned by 1 / a:
// 1e4 tol there.
template <typename T>
void compare(const Primitive<T>& closed, const Primitive<T>& quartic, const Surface& surface, const Ray<T>& ray,
             double tol, bool grazing, Compared& c) {
  const SpanList<T> a = spansOf(closed, ray), b = spansOf(quartic, ray);
  const Vec3d o(ray.origin), d(ray.direction);
  if (a.empty() && b.empty()) {
    ++c.bothMissed;
    return;
  }
  if (a.size() != b.size()) {
    const auto close = [](double x, double y) { return x == y || std::abs(x - y) < 1e-2; };  // equal infinities too
    const SpanList<T>& longer = a.size() > b.size() ? a : b;
    const SpanList<T>& shorter = a.size() > b.size() ? b : a;
    for (const Span<T>& s : longer) {
      bool matched = false;
      for (const Span<T>& other : shorter)
        matched = matched || close(double(s.enter.t), double(other.enter.t)) || close(double(s.leave.t), double(other.leave.t));
      if (matched || !std::isfinite(double(s.enter.t)) || !std::isfinite(double(s.leave.t))) continue;
      const double off = surface.distance(o + d * (0.5 * double(s.enter.t + s.leave.t)));
      INFO("a span of the " << (a.size() > b.size() ? "closed form" : "quartic") << " alone, its middle " << off
                            << " from the surface");
      REQUIRE(off < tol / 20);
    }
    if (!grazing) ++c.grazes;
    return;
  }
  for (std::size_t k = 0; k < a.size(); ++k)
    for (const auto& [pa, pb] : {std::pair{a[k].enter, b[k].enter}, std::pair{a[k].leave, b[k].leave}}) {
      if (!std::isfinite(double(pa.t)) || !std::isfinite(double(pb.t))) {
        REQUIRE(pa.t == pb.t);
        ++c.unbounded;
        continue;
      }
      const double t = double(pb.t), dt = std::abs(double(pa.t) - t);
      const double cosine = std::abs(glm::dot(Vec3d(pb.normal), d)) / glm::length(d);
      const double bound = (std::abs(t) > 100.0 ? 1e4 : 1.0) * tol * (1.0 + std::abs(t));
      INFO("t " << double(pa.t) << " against the quartic's " << t << ", cosine " << cosine);
      REQUIRE(dt * cosine <= bound);
      if (cosine > 0.1) {
        REQUIRE(dt <= bound);
        CHECK(glm::dot(Vec3d(pa.normal), Vec3d(pb.normal)) > 1.0 - 1e3 * tol);
      }
      CHECK(pa.material == pb.material);
    }
  ++c.agreed;
}

Vec3d randomIn(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  return {u(rng), u(rng), u(rng)};
}

}  // namespace

TEMPLATE_TEST_CASE("the closed-form quadric gives the quartic quadric's spans", "[shapes][quadric]", float, double) {
  using T = TestType;
  const double tol = std::is_same_v<T, float> ? 2e-4 : 1e-9;
  const std::pair<const char*, QuarticShape> shapes[] = {
      {"cylinder", cylinder(0.42)},           {"ellipsoid", ellipsoid(1.0, 0.5, 0.8)},
      {"cone", cone(0.7)},                    {"paraboloid", paraboloid(0.8)},
      {"hyperboloid, one sheet", hyperboloid(0.5, 0.7, true)}, {"hyperboloid, two sheets", hyperboloid(0.5, 0.7, false)},
  };
  const Mat4d placements[] = {
      glm::translate(Mat4d(1), Vec3d(0.5, -1, 2)) * glm::rotate(Mat4d(1), 0.7, glm::normalize(Vec3d(1, 2, 0.5))),
      glm::scale(glm::rotate(Mat4d(1), 1.1, glm::normalize(Vec3d(0.3, -1, 2))), Vec3d(1.0, 2.5, 0.5)),
  };
  for (const auto& [name, shape] : shapes)
    for (const Mat4d& m : placements) {
      const auto closed = makeQuadricLeaf<T>(shape.f, shape.bounds, m, 6);
      const auto quartic = makeQuarticLeaf<T>(shape.f, shape.bounds, m, 6);
      const Surface surface{shape, glm::inverse(m)};
      REQUIRE(closed->bounds().lo == quartic->bounds().lo);
      REQUIRE(closed->bounds().hi == quartic->bounds().hi);
      std::mt19937 rng(41);
      Compared c;
      const Vec3d centre(m * glm::dvec4(0, 0, 0, 1));
      for (int n = 0; n < 3000; ++n) {
        Vec3d o = centre + randomIn(rng, n % 2 ? 1.0 : 5.0);
        Vec3d target = centre + randomIn(rng, 1.0);
        if (n % 10 == 0) {  // graze: along the tangent plane at a surface point, off it by 0 to 1e-3
          const SpanList<T> s = spansOf(*quartic, makeRay<T>(o, target - o));
          if (!s.empty() && std::isfinite(double(s[0].enter.t))) {
            const Vec3d p = o + (target - o) * double(s[0].enter.t), normal(s[0].enter.normal);
            const Vec3d along = glm::normalize(glm::cross(normal, randomIn(rng, 1.0)));
            const double off[] = {0.0, 1e-6, -1e-6, 1e-3, -1e-3};
            target = p + normal * off[n / 10 % 5];
            o = target - along * 3.0;
          }
        }
        if (glm::length(target - o) < 1e-6) continue;
        compare<T>(*closed, *quartic, surface, makeRay<T>(o, glm::normalize(target - o)), tol, n % 10 == 0, c);
      }
      INFO(name << ": agreed " << c.agreed << ", both missed " << c.bothMissed << ", unbounded ends "
                << c.unbounded << ", grazes " << c.grazes);
      CHECK(c.agreed > 1000);
      CHECK(c.grazes <= 30);  // of the 2,700 rays not aimed to graze, at most about 1 %
    }
}

TEST_CASE("the closed-form quadric refuses what the quartic leaf refuses") {
  const QuarticShape tube = cylinder(1.0);
  Mat4d singular(1);
  singular[2][2] = 0.0;
  singular[2][1] = 0.0;
  singular[2][0] = 0.0;
  CHECK_THROWS_AS(makeQuadricLeaf<double>(tube.f, tube.bounds, singular, 0), Error);
  CHECK_THROWS_AS(makeQuarticLeaf<double>(tube.f, tube.bounds, singular, 0), Error);
  CHECK_THROWS_AS(makeQuadricLeaf<double>(torus(1.0, 0.2).f, torus(1.0, 0.2).bounds, Mat4d(1), 0), Error);
}
