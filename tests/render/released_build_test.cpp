// Building from a NodeDesc&& (buildPrimitive, Renderer(SceneDesc&&)) frees
// each set operation's operand descriptions as it goes, so a scatter's
// descriptions and its BVH's build do not take memory at once
// (docs/memory.md). The tree it builds must be the one the kept build makes:
// every ray answered with the same bits, every row the same pixels.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "render/renderer.hpp"
#include "render/scene/scene.hpp"
#include "tests/render/scene_test_util.hpp"

using namespace lattice;
using lattice::testing::TempScene;

namespace {

// Nested unions with transforms, materials and a difference: more operands
// than a BVH leaf holds, so the unions build trees.
const char* const kScene = R"([materials.red]
diffuse = [0.9, 0.1, 0.1]

[[lights]]
position = [3, 4, -6]
intensity = 1

[[objects]]
type = "union"
translate = [0.1, 0, 0]
material = "red"
children = [
  { type = "sphere", radius = 0.3, translate = [-1, 0, 0] },
  { type = "sphere", radius = 0.3, translate = [-0.5, 0.4, 0] },
  { type = "sphere", radius = 0.3, translate = [0, -0.4, 0.2] },
  { type = "sphere", radius = 0.3, translate = [0.5, 0.4, 0] },
  { type = "sphere", radius = 0.3, translate = [1, 0, 0.3] },
  { type = "union", scale = 0.5, children = [
      { type = "sphere", radius = 0.4, translate = [0, 1.5, 0] },
      { type = "sphere", radius = 0.4, translate = [0.8, 1.5, 0] },
      { type = "sphere", radius = 0.4, translate = [-0.8, 1.5, 0] } ] },
]

[[objects]]
type = "difference"
translate = [0, -1, 0]
children = [ { type = "sphere", radius = 0.6 }, { type = "sphere", radius = 0.4, translate = [0.3, 0.3, -0.3] } ]
)";

bool sameHit(const Primitive<double>& a, const Primitive<double>& b, const Ray<double>& ray) {
  Hit<double> ha, hb;
  const bool fa = a.firstHit(ray, 0.0, 1e9, ha), fb = b.firstHit(ray, 0.0, 1e9, hb);
  if (fa != fb) return false;
  if (!fa) return true;
  return std::memcmp(&ha.t, &hb.t, sizeof ha.t) == 0 && std::memcmp(&ha.normal, &hb.normal, sizeof ha.normal) == 0 &&
         ha.material == hb.material;
}

}  // namespace

TEST_CASE("released build: buildPrimitive of a NodeDesc&& frees the operands and builds the same tree") {
  TempScene file(kScene);
  const SceneDesc scene = file.load();
  NodeDesc taken = scene.root;
  REQUIRE_FALSE(taken.children.empty());
  const auto kept = buildPrimitive<double>(scene.root, Mat4d(1.0), BuildOptions{});
  const auto released = buildPrimitive<double>(std::move(taken), Mat4d(1.0), BuildOptions{});
  CHECK(taken.children.empty());       // the operands' descriptions are gone
  CHECK(taken.children.capacity() == 0);  // and their storage with them
  int hits = 0;
  for (int y = -40; y <= 40; ++y)
    for (int x = -40; x <= 40; ++x) {
      const Ray<double> ray{Vec3d(0.0, 0.0, -5.0), Vec3d(x / 40.0 * 0.35, y / 40.0 * 0.35, 1.0)};
      REQUIRE(sameHit(*kept, *released, ray));
      Hit<double> h;
      if (kept->firstHit(ray, 0.0, 1e9, h)) ++hits;
    }
  CHECK(hits > 1000);  // the rays meet the solids, so the comparison means something
}

TEST_CASE("released build: Renderer(SceneDesc&&) renders the rows Renderer(const SceneDesc&) does") {
  TempScene file(kScene);
  const SceneDesc scene = file.load();
  SceneDesc taken = scene;
  const RenderSettings settings{48, 32, 1, {}};
  Renderer<Fixed32> kept(scene, settings);
  Renderer<Fixed32> released(std::move(taken), settings);
  CHECK(taken.root.children.empty());
  CHECK(taken.lights.size() == scene.lights.size());  // only the node tree is taken
  std::vector<Color18> a(48), b(48);
  bool lit = false;
  for (int y = 0; y < 32; ++y) {
    kept.row(y, a);
    released.row(y, b);
    REQUIRE(std::memcmp(a.data(), b.data(), a.size() * sizeof(Color18)) == 0);
    for (const Color18& c : a) lit = lit || !(c == a.front());
  }
  CHECK(lit);  // not a blank picture
}
