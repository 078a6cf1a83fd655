// A baked union of lattice instances (lht/leaf/baked_lattice_union.hpp): the
// firmware's scatter as constant data must answer every ray exactly as the
// CSG union of the instance leaves the renderer builds from the scene, and
// render the same picture, in fixed point.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include "foundation/fixed.hpp"
#include "lht/leaf/baked_lattice_union.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"
#include "tests/support/hair_scene.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

using F = Fixed32;

SceneWithLattices hairScene(int hairs) {
  testing::HairScene scene;
  scene.size = 40;
  scene.hairs = hairs;
  scene.fur = true;
  scene.fillLight = true;
  scene.floor = true;
  return parseSceneWithLattices(scene.toml(), "hair.toml");
}

bool sameHit(const Hit<F>& a, const Hit<F>& b) {
  return a.t == b.t && a.normal == b.normal && a.material == b.material;
}

}  // namespace

TEST_CASE("baked lattice union: every query answers as the CSG union of the instance leaves, bit for bit") {
  const SceneWithLattices loaded = hairScene(80);
  const NodeDesc& scatter = loaded.scene.root.children[1];
  REQUIRE(scatter.children.size() == 80);
  const std::optional<LatticeUnionArrays> arrays = collectLatticeUnion(scatter, Mat4d(1.0), 0);
  REQUIRE(arrays);
  CHECK(arrays->placements.size() == 80);
  CHECK(arrays->bvh.nodes().size() >= 2);
  const PrimitivePtr<F> built = buildPrimitive<F>(scatter, Mat4d(1.0), BuildOptions{}, 0);
  const PrimitivePtr<F> baked = makeBakedLatticeUnion(arrays->view("hair"));
  CHECK(baked->bounds().lo == built->bounds().lo);
  CHECK(baked->bounds().hi == built->bounds().hi);

  // Rays from around the sphere towards it (primary-like) and from points on
  // and near it outwards (shadow-like, many starting inside a hair's box).
  std::mt19937 random(24);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int hits = 0, shadowed = 0, spanRays = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec3d from = n % 2 == 0 ? Vec3d(unit(random), unit(random), unit(random)) * 3.0
                                  : Vec3d(unit(random), unit(random), unit(random)) * 1.05;
    const Vec3d to = Vec3d(unit(random), unit(random), unit(random)) * (n % 2 == 0 ? 0.9 : 3.0);
    const Ray<F> ray{Vec3<F>(from), Vec3<F>(to - from)};
    const F tmin = F(0.0001), tmax = n % 3 == 0 ? F(1) : std::numeric_limits<F>::infinity();
    Hit<F> a, b;
    const bool ha = built->firstHit(ray, tmin, tmax, a), hb = baked->firstHit(ray, tmin, tmax, b);
    REQUIRE(ha == hb);
    if (ha) {
      ++hits;
      REQUIRE(sameHit(a, b));
    }
    const bool sa = built->anyHit(ray, tmin, tmax);
    REQUIRE(sa == baked->anyHit(ray, tmin, tmax));
    shadowed += sa;
    bool ia = false, ib = false;
    Hit<F> ea, eb;
    const bool fa = built->firstEnter(ray, tmin, tmax, ea, ia), fb = baked->firstEnter(ray, tmin, tmax, eb, ib);
    REQUIRE(fa == fb);
    REQUIRE(ia == ib);
    if (fa) REQUIRE(sameHit(ea, eb));
    SpanList<F> la, lb;
    built->spans(ray, tmin, tmax, la);
    baked->spans(ray, tmin, tmax, lb);
    REQUIRE(la.size() == lb.size());
    spanRays += !la.empty();
    for (std::size_t k = 0; k < la.size(); ++k) {
      REQUIRE(sameHit(la[k].enter, lb[k].enter));
      REQUIRE(sameHit(la[k].leave, lb[k].leave));
    }
  }
  // The rays exercised hits, shadows and span lists, not only misses.
  CHECK(hits > 100);
  CHECK(shadowed > 100);
  CHECK(spanRays > 100);
}

TEST_CASE("baked lattice union: a scene with its scatter baked renders the same fixed-point picture") {
  const SceneWithLattices loaded = hairScene(120);
  const std::optional<LatticeUnionArrays> arrays = collectLatticeUnion(loaded.scene.root.children[1], Mat4d(1.0), 0);
  REQUIRE(arrays);
  SceneDesc baked = loaded.scene;
  NodeDesc& scatter = baked.root.children[1];
  const NodeDesc original = scatter;
  scatter = NodeDesc::makeLeaf(makeBakedLatticeUnionDesc(arrays->view("hair")));
  scatter.transform = original.transform;
  scatter.material = original.material;

  RenderSettings settings;
  settings.threads = 1;
  Renderer<F> a(loaded.scene, settings), b(baked, settings);
  std::vector<Color18> rowA(static_cast<std::size_t>(a.width())), rowB(rowA.size());
  int lit = 0;
  for (int y = 0; y < a.height(); ++y) {
    a.row(y, rowA);
    b.row(y, rowB);
    REQUIRE(rowA == rowB);
    for (Color18 c : rowA) lit += c != rowA.front();
  }
  CHECK(lit > 0);  // not a blank picture
}

TEST_CASE("baked lattice union: it refuses what it was not baked for, naming the fix") {
  const SceneWithLattices loaded = hairScene(10);
  const NodeDesc& scatter = loaded.scene.root.children[1];
  const std::optional<LatticeUnionArrays> arrays = collectLatticeUnion(scatter, Mat4d(1.0), 0);
  REQUIRE(arrays);
  const NodeDesc leaf = NodeDesc::makeLeaf(makeBakedLatticeUnionDesc(arrays->view("hair")));
  // Another arithmetic.
  CHECK_THROWS_WITH(buildPrimitive<double>(leaf, Mat4d(1.0), BuildOptions{}, 0),
                    Catch::Contains("--arith fixed"));
  // Another placement than the bake's.
  CHECK_THROWS_WITH(buildPrimitive<F>(leaf, glm::translate(Mat4d(1.0), Vec3d(0.5, 0.0, 0.0)), BuildOptions{}, 0),
                    Catch::Contains("bake the scene again"));
  // One instance is not a tree: the union is then baked node by node.
  NodeDesc one = scatter;
  one.children.resize(1);
  CHECK_FALSE(collectLatticeUnion(one, Mat4d(1.0), 0));
}
