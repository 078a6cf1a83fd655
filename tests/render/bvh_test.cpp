// The BVH: structure invariants, and a union over a BVH agreeing exactly with
// a flat loop over the same thousands of spheres.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <set>

#include "geometry_checks.hpp"
#include "foundation/fixed.hpp"
#include "render/accel/bvh.hpp"
#include "render/shapes/csg.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "render/shapes/span_ops.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

struct Ball {
  Vec3d centre;
  double radius;
};

std::vector<Ball> randomBalls(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-10, 10), rad(0.05, 0.4);
  std::vector<Ball> balls;
  for (int i = 0; i < n; ++i) balls.push_back({Vec3d(pos(rng), pos(rng), pos(rng)), rad(rng)});
  return balls;
}

template <typename T>
PrimitivePtr<T> leaf(const Ball& b, MaterialId m) {
  QuarticShape s = sphere(b.radius);
  return makeQuarticLeaf<T>(s.f, s.bounds, glm::translate(Mat4d(1), b.centre), m);
}

}  // namespace

TEMPLATE_TEST_CASE("BVH nodes contain their items and each item appears once", "[bvh]", float, double) {
  using T = TestType;
  std::vector<Bounds<T>> boxes;
  for (const Ball& b : randomBalls(3000, 5))
    boxes.push_back({Vec3<T>(b.centre - b.radius), Vec3<T>(b.centre + b.radius)});
  // Some identical boxes, which no plane can separate.
  for (int n = 0; n < 50; ++n) boxes.push_back(boxes[0]);
  Bvh<T> bvh(boxes);
  std::multiset<std::uint32_t> items(bvh.items().begin(), bvh.items().end());
  REQUIRE(items.size() == boxes.size());
  for (std::uint32_t n = 0; n < boxes.size(); ++n) REQUIRE(items.count(n) == 1);
  const auto& nodes = bvh.nodes();
  // Recursively: each node's box contains its items' boxes.
  std::function<void(std::uint32_t, const Bounds<T>&)> check = [&](std::uint32_t index, const Bounds<T>& parent) {
    const auto& node = nodes[index];
    REQUIRE(glm::all(glm::greaterThanEqual(node.box.lo, parent.lo)));
    REQUIRE(glm::all(glm::lessThanEqual(node.box.hi, parent.hi)));
    if (node.count > 0) {
      for (std::uint32_t n = 0; n < node.count; ++n) {
        const Bounds<T>& b = boxes[bvh.items()[node.first + n]];
        REQUIRE(glm::all(glm::greaterThanEqual(b.lo, node.box.lo)));
        REQUIRE(glm::all(glm::lessThanEqual(b.hi, node.box.hi)));
      }
    } else {
      check(index + 1, node.box);
      check(node.first, node.box);
    }
  };
  check(0, nodes[0].box);
  // A log-depth tree, not a list.
  REQUIRE(bvh.depth() < 40);
  REQUIRE(nodes.size() > 100);
}

TEMPLATE_TEST_CASE("a union over a BVH equals a flat union of thousands of random spheres", "[bvh]", float, double) {
  using T = TestType;
  std::vector<Ball> balls = randomBalls(3000, 9);
  std::vector<PrimitivePtr<T>> flat, children;
  for (std::size_t n = 0; n < balls.size(); ++n) {
    flat.push_back(leaf<T>(balls[n], MaterialId(n)));
    children.push_back(leaf<T>(balls[n], MaterialId(n)));
  }
  // An unbounded child too: the floor z < -9.
  QuarticShape floorShape = halfSpace(Vec3d(0, 0, 1), -9);
  flat.push_back(makeQuarticLeaf<T>(floorShape.f, floorShape.bounds, Mat4d(1), 99999));
  children.push_back(makeQuarticLeaf<T>(floorShape.f, floorShape.bounds, Mat4d(1), 99999));
  auto u = makeCsgNode<T>(CsgOp::Union, std::move(children));

  std::mt19937 rng(17);
  std::uniform_real_distribution<double> pos(-12, 12), len(1, 40);
  int hits = 0;
  for (int n = 0; n < 400; ++n) {
    Vec3d o(pos(rng), pos(rng), pos(rng) * 0.5 + 4);
    Ray<T> ray = makeRay<T>(o, randomUnit(rng));
    T tmin = T(0), tmax = T(len(rng));
    // Flat reference: every child's spans, merged by the union rule.
    SpanList<T> expected;
    for (const auto& p : flat) {
      SpanList<T> l;
      p->spans(ray, tmin, tmax, l);
      for (const auto& s : l) expected.push_back(s);
    }
    coalesceSpans(expected);
    SpanList<T> got = spansOf(*u, ray, tmin, tmax);
    REQUIRE(got.size() == expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      REQUIRE(got[k].enter.t == expected[k].enter.t);
      REQUIRE(got[k].leave.t == expected[k].leave.t);
      REQUIRE(got[k].enter.material == expected[k].enter.material);
      REQUIRE(got[k].leave.material == expected[k].leave.material);
    }
    Hit<T> want, hit;
    bool wantAny = firstCrossing(expected, tmin, tmax, want);
    bool gotAny = u->firstHit(ray, tmin, tmax, hit);
    REQUIRE(gotAny == wantAny);
    REQUIRE(u->anyHit(ray, tmin, tmax) == wantAny);
    if (gotAny) {
      ++hits;
      REQUIRE(hit.t == want.t);
      REQUIRE(hit.material == want.material);
      REQUIRE(hit.normal == want.normal);
    }
  }
  REQUIRE(hits > 50);
}

// Bvh::view (a baked scene's constant arrays, docs/firmware.md): a tree over
// another tree's nodes and items visits the same items in the same order,
// front to back and all, stopping where the built one stops.
TEMPLATE_TEST_CASE("a BVH view over a built tree's arrays answers as the tree", "[bvh]", float, Fixed32) {
  using T = TestType;
  std::vector<Bounds<T>> boxes;
  for (const Ball& b : randomBalls(500, 9))
    boxes.push_back({Vec3<T>(b.centre - b.radius), Vec3<T>(b.centre + b.radius)});
  const Bvh<T> built(boxes);
  const std::vector<typename Bvh<T>::Node> nodes(built.nodes().begin(), built.nodes().end());
  const std::vector<std::uint32_t> items(built.items().begin(), built.items().end());
  const Bvh<T> view = Bvh<T>::view(nodes, items, built.depth());
  REQUIRE(view.nodes().data() == nodes.data());  // the arrays given, not a copy
  CHECK(view.depth() == built.depth());
  CHECK(Bvh<T>::view({}, {}, 0).empty());

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(-12, 12);
  int visited = 0;
  for (int n = 0; n < 300; ++n) {
    const Vec3d from(pos(rng), pos(rng), pos(rng)), to(pos(rng), pos(rng), pos(rng));
    const Ray<T> ray{Vec3<T>(from), Vec3<T>(to - from)};
    std::vector<std::uint32_t> a, b;
    built.visitAll(ray, T(0), T(1), [&](std::uint32_t i) { a.push_back(i); return false; });
    view.visitAll(ray, T(0), T(1), [&](std::uint32_t i) { b.push_back(i); return false; });
    REQUIRE(a == b);
    visited += static_cast<int>(a.size());
    // Front to back, lowering the limit at every third item.
    std::vector<std::uint32_t> fa, fb;
    T limitA(1), limitB(1);
    built.visitFrontToBack(ray, T(0), limitA, [&](std::uint32_t i, T& lim) {
      fa.push_back(i);
      if (fa.size() % 3 == 0) lim = lim * T(0.5);
    });
    view.visitFrontToBack(ray, T(0), limitB, [&](std::uint32_t i, T& lim) {
      fb.push_back(i);
      if (fb.size() % 3 == 0) lim = lim * T(0.5);
    });
    REQUIRE(fa == fb);
    CHECK(limitA == limitB);
  }
  CHECK(visited > 50);  // the rays met boxes, not only empty space (90 item visits in all, measured)
}
