// Who blocks a shadow ray (Primitive::occluder, render/shapes/union_core.hpp)
// over a CSG tree with every kind of child: capsule leaves, a nested union,
// a difference, and the quartic capsule (a union whose box its caller cut).
// The node named blocks the ray itself, exists exactly when anyHit says yes,
// is handed down through plain unions but never from inside a cut one, and
// the row's cache (render/scene/occluder_cache.hpp) answers a stream of
// coherent and random segments as anyHit does.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <random>
#include <set>

#include "geometry_checks.hpp"
#include "render/scene/occluder_cache.hpp"
#include "render/shapes/composite_shapes.hpp"
#include "render/shapes/csg.hpp"

using namespace lattice;
using namespace lattice::testing;

TEMPLATE_TEST_CASE("occluder: the node named blocks the ray, and a cut union names itself", "[csg][occluder]", float,
                   double) {
  using T = TestType;
  const auto at = [](double x, double y, double z) { return glm::translate(Mat4d(1), Vec3d(x, y, z)); };
  // A nested plain union of three balls, a ball with a bite out of it, a capsule, and the quartic
  // capsule (its union's box is cut by the caller).
  std::vector<PrimitivePtr<T>> balls;
  std::set<const Primitive<T>*> handedDown;
  for (int k = 0; k < 3; ++k) {
    balls.push_back(makeCapsule<T>(0.3, 0.0, at(-1.5 + 0.7 * k, 0.8, 0), 1));
    handedDown.insert(balls.back().get());
  }
  std::vector<PrimitivePtr<T>> bite;
  bite.push_back(makeCapsule<T>(0.5, 0.0, at(1.2, -0.6, 0.3), 2));
  bite.push_back(makeCapsule<T>(0.35, 0.0, at(1.5, -0.4, 0.0), 2));
  std::vector<PrimitivePtr<T>> top;
  top.push_back(makeCsgNode<T>(CsgOp::Union, std::move(balls)));
  top.push_back(makeCsgNode<T>(CsgOp::Difference, std::move(bite)));
  top.push_back(makeCapsule<T>(0.25, 1.5, at(-0.8, -0.9, -0.2), 3));
  top.push_back(makeQuarticCapsule<T>(0.2, 1.2, at(0.4, 0.1, -0.8), 4));
  const Primitive<T>* difference = top[1].get();
  const Primitive<T>* capsule = top[2].get();
  const Primitive<T>* cutUnion = top[3].get();
  handedDown.insert({difference, capsule, cutUnion});
  const PrimitivePtr<T> scene = makeCsgNode<T>(CsgOp::Union, std::move(top));

  std::mt19937 rng(53);
  std::uniform_real_distribution<double> u(-2.2, 2.2), reach(0.2, 1.2);
  std::set<const Primitive<T>*> named;
  int blocked = 0;
  OccluderCache<T> cache(2);
  Vec3d from(0.0), to(0.0);
  for (int n = 0; n < 6000; ++n) {
    // Runs of rays a little apart (a row's neighbours), now and then a new start.
    if (n % 20 == 0) from = Vec3d(u(rng), u(rng), u(rng)), to = Vec3d(u(rng), u(rng), u(rng));
    from += randomUnit(rng) * 0.02;
    const Ray<T> ray = makeRay<T>(from, (to - from) * reach(rng));
    const bool expected = scene->anyHit(ray, T(0), T(1));
    const Primitive<T>* who = scene->occluder(ray, T(0), T(1));
    REQUIRE((who != nullptr) == expected);
    REQUIRE(cache.blocked(*scene, ray, static_cast<std::size_t>(n % 2)) == expected);
    if (!who) continue;
    ++blocked;
    REQUIRE(who->anyHit(ray, T(0), T(1)));
    REQUIRE(handedDown.count(who) == 1);  // a ball, the difference, the capsule or the cut union whole
    named.insert(who);
  }
  CHECK(blocked > 600);
  CHECK(named.count(difference) == 1);
  CHECK(named.count(capsule) == 1);
  CHECK(named.count(cutUnion) == 1);
  CHECK(named.size() >= 5);  // some of the nested union's balls too
}
