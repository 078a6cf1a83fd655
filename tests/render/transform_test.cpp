// Transforms and materials on inner CSG nodes are pushed down to the leaves
// when the tree is built (thesis sec. 3.1, fig. 4).
#include <catch2/catch.hpp>

#include "render/scene/scene.hpp"
#include "loader/scene_loader.hpp"
#include "tests/render/scene_test_util.hpp"

using namespace lattice;
using lattice::testing::TempScene;

namespace {

// Where a ray along +z through (x, y) first meets the solid, if it does.
std::optional<Hit<double>> probe(const Primitive<double>& p, double x, double y) {
  Hit<double> hit;
  if (!p.firstHit(Ray<double>{Vec3d(x, y, -100), Vec3d(0, 0, 1)}, 0.0, 1e9, hit)) return std::nullopt;
  return hit;
}

}  // namespace

TEST_CASE("transform: transforms on inner nodes reach the leaves") {
  // union: scale 2 then translate (2, 0, 0); its sphere (radius 0.5) sits at
  // (1, 0, 0) locally. In the world: centre 2 + 2 * 1 = 4, radius 1.
  TempScene file(R"([[objects]]
type = "union"
scale = 2
translate = [2, 0, 0]
children = [ { type = "sphere", radius = 0.5, translate = [1, 0, 0] } ]
)");
  SceneDesc s = file.load();
  auto p = buildPrimitive<double>(s.root, Mat4d(1.0), BuildOptions{});
  auto hit = probe(*p, 4.0, 0.0);
  REQUIRE(hit);
  REQUIRE(hit->t == Approx(100.0 - 1.0));  // enters at z = -1
  REQUIRE(hit->normal.z == Approx(-1.0));
  REQUIRE(probe(*p, 4.99, 0.0));
  REQUIRE_FALSE(probe(*p, 5.01, 0.0));
  REQUIRE_FALSE(probe(*p, 2.0, 0.0));  // where the sphere would be without the child's own translate
  // The parent matrix a caller passes in comes first of all.
  Mat4d lift(1.0);
  lift[3] = glm::dvec4(0, 10, 0, 1);
  auto lifted = buildPrimitive<double>(s.root, lift, BuildOptions{});
  REQUIRE(probe(*lifted, 4.0, 10.0));
  REQUIRE_FALSE(probe(*lifted, 4.0, 0.0));
}

TEST_CASE("transform: a node's own transform is scale then rotate then translate") {
  // An ellipsoid long along x, scaled along x by 2, turned 90 degrees about z
  // (x -> y), then moved to (0, 0, 5): it is long along y, 4 from its centre.
  TempScene file(R"([[objects]]
type = "ellipsoid"
radii = [2, 0.5, 0.5]
scale = [2, 1, 1]
rotate = { axis = [0, 0, 1], degrees = 90 }
translate = [0, 0, 5]
)");
  auto p = buildPrimitive<double>(file.load().root, Mat4d(1.0), BuildOptions{});
  REQUIRE(probe(*p, 0.0, 3.9));
  REQUIRE_FALSE(probe(*p, 0.0, 4.1));
  REQUIRE_FALSE(probe(*p, 0.6, 0.0));
  REQUIRE(probe(*p, 0.0, 0.0)->t == Approx(105.0 - 0.5));
}

TEST_CASE("transform: materials are inherited down the tree unless a node sets its own") {
  TempScene file(R"([materials.a]
diffuse = 1
[materials.b]
diffuse = 0.5
[[objects]]
type = "union"
material = "a"
children = [
  { type = "sphere", radius = 1 },
  { type = "sphere", radius = 1, translate = [5, 0, 0], material = "b" },
]
)");
  SceneDesc s = file.load();
  auto p = buildPrimitive<double>(s.root, Mat4d(1.0), BuildOptions{});
  REQUIRE(probe(*p, 0.0, 0.0)->material == *s.findMaterial("a"));
  REQUIRE(probe(*p, 5.0, 0.0)->material == *s.findMaterial("b"));
  // Without any material the default (id 0) is used.
  TempScene plain("[[objects]]\ntype = \"sphere\"\nradius = 1\n");
  auto q = buildPrimitive<double>(plain.load().root, Mat4d(1.0), BuildOptions{});
  REQUIRE(probe(*q, 0.0, 0.0)->material == 0);
}

TEST_CASE("transform: CSG difference from a scene file makes a sphere with a hole") {
  TempScene file(R"([[objects]]
type = "difference"
children = [ { type = "sphere", radius = 1 }, { type = "cylinder", radius = 0.4 } ]
)");
  auto p = buildPrimitive<double>(file.load().root, Mat4d(1.0), BuildOptions{});
  // The cylinder runs along z, the probes too: straight through the hole.
  REQUIRE_FALSE(probe(*p, 0.0, 0.0));
  REQUIRE_FALSE(probe(*p, 0.39, 0.0));
  auto wall = probe(*p, 0.6, 0.0);
  REQUIRE(wall);
  REQUIRE(wall->t == Approx(100.0 - std::sqrt(1.0 - 0.36)));
}
