// Scene files: what a good file turns into, and one test per kind of mistake,
// each checking the message names file:line and what was expected.
#include <catch2/catch.hpp>

#include "loader/scene_loader.hpp"
#include "tests/render/scene_test_util.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using lattice::testing::TempScene;

namespace {

const char* kSphere = "[[objects]]\ntype = \"sphere\"\nradius = 1\n";

// Loads `text` expecting an Input error whose message contains
// "<file>:<line>:" and every one of `expected`.
void requireInputError(const std::string& text, int line, std::initializer_list<std::string> expected,
                       const SceneFormat& format = builtinSceneFormat()) {
  TempScene scene(text);
  try {
    scene.load(format);
    FAIL("expected an error for:\n" << text);
  } catch (const Error& e) {
    const std::string message = e.what();
    INFO("message: " << message);
    REQUIRE(e.kind() == ErrorKind::Input);
    if (line > 0) REQUIRE_THAT(message, Catch::StartsWith(fmt::format("{}:{}:", scene.path().string(), line)));
    for (const auto& piece : expected) REQUIRE_THAT(message, Catch::Contains(piece));
  }
}

}  // namespace

TEST_CASE("scene: a complete file becomes the description it says") {
  TempScene file(R"(
[options]
width = 64
height = 48
ambient = [0.1, 0.2, 0.3]
K = 2.5
background = 0.5
shadows = false

[camera]
type = "look_at"
eye = [1, 2, 3]
target = [0, 0, 0]
fov = 40

[materials.red]
diffuse = [1, 0, 0]
specular = 0.25
shininess = [10, 20, 30]

[[lights]]
position = [0, 5, 0]
intensity = [1, 2, 3]

[[lights]]
position = [1, 1, 1]
intensity = 4

[[objects]]
type = "sphere"
radius = 2
material = "red"

[[objects]]
type = "torus"
major = 1
minor = 0.25
)");
  SceneDesc s = file.load();
  REQUIRE(s.options.width == 64);
  REQUIRE(s.options.height == 48);
  REQUIRE(s.options.ambient == Vec3d(0.1, 0.2, 0.3));
  REQUIRE(s.options.attenuationK == 2.5);
  REQUIRE(s.options.background == Vec3d(0.5));
  REQUIRE_FALSE(s.options.shadows);
  REQUIRE(s.camera.kind == CameraDesc::Kind::LookAt);
  REQUIRE(s.camera.eye == Vec3d(1, 2, 3));
  REQUIRE(s.camera.fovDegrees == 40);
  REQUIRE(s.lights.size() == 2);
  REQUIRE(s.lights[0].intensity == Vec3d(1, 2, 3));
  REQUIRE(s.lights[1].intensity == Vec3d(4));
  REQUIRE(s.materials.size() == 2);  // "default" + "red"
  REQUIRE(s.findMaterial("red") == MaterialId{1});
  REQUIRE(s.materials[1].material.diffuse == Vec3d(1, 0, 0));
  REQUIRE(s.materials[1].material.shininess == Vec3d(10, 20, 30));
  // Two top-level objects: an implicit union; the sphere carries "red".
  REQUIRE(s.root.kind == NodeDesc::Kind::Union);
  REQUIRE(s.root.children.size() == 2);
  REQUIRE(s.root.children[0].kind == NodeDesc::Kind::Leaf);
  REQUIRE(s.root.children[0].material == MaterialId{1});
  REQUIRE(s.root.children[0].leaf->describe() == "sphere");
  REQUIRE_FALSE(s.root.children[1].material.has_value());
  REQUIRE(s.root.children[1].leaf->objectBounds().hi.x == Approx(1.25));
}

TEST_CASE("scene: the thesis camera keys") {
  TempScene file(std::string("[camera]\ntype = \"thesis\"\ndistance = 3\nwidth = 2\nheight = 1.5\n") + kSphere);
  SceneDesc s = file.load();
  REQUIRE(s.camera.kind == CameraDesc::Kind::Thesis);
  REQUIRE(s.camera.distance == 3);
  REQUIRE(s.camera.displayWidth == 2);
  REQUIRE(s.camera.displayHeight == 1.5);
}

TEST_CASE("scene: explicit quartic coefficients as a table and as a list") {
  TempScene asTable(R"([[objects]]
type = "quartic"
coefficients = { x2y0z0 = 1, x0y2z0 = 1, x0y0z2 = 1, x0y0z0 = -4 }
bounds = { min = [-2, -2, -2], max = [2, 2, 2] }
)");
  SceneDesc s = asTable.load();
  REQUIRE(s.root.leaf->describe() == "quartic");
  REQUIRE(s.root.leaf->objectBounds().lo == Vec3d(-2));
  // The same sphere of radius 2 as a list in degree order: 1, x, y, z, x^2, xy, xz, y^2, yz, z^2, ...
  std::string list = "[[objects]]\ntype = \"quartic\"\ncoefficients = [-4, 0, 0, 0, 1, 0, 0, 1, 0, 1";
  for (int i = 10; i < 35; ++i) list += ", 0";
  list += "]\n";
  TempScene asList(list);
  SceneDesc l = asList.load();
  auto p = l.root.leaf->build<double>(Mat4d(1.0), 0, BuildOptions{});
  Hit<double> hit;
  REQUIRE(p->firstHit(Ray<double>{Vec3d(0, 0, -10), Vec3d(0, 0, 1)}, 0.0, 100.0, hit));
  REQUIRE(hit.t == Approx(8.0));
}

TEST_CASE("scene errors: not TOML") {
  requireInputError("[options]\nwidth = = 3\n", 2, {"not valid TOML"});
}

TEST_CASE("scene errors: unknown keys") {
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = 1\nradios = 2\n", 4,
                    {"unknown key 'radios'", "radius"});
  requireInputError(std::string("[options]\nwidht = 3\n") + kSphere, 2, {"unknown key 'widht'", "width"});
  requireInputError(std::string("[camera]\ntype = \"thesis\"\ndistance = 1\nwidth = 1\nheight = 1\nfov = 3\n") + kSphere,
                    6, {"unknown key 'fov'"});
}

TEST_CASE("scene errors: unknown section or object type or material") {
  requireInputError(std::string("[lamps]\nx = 1\n") + kSphere, 1, {"unknown section 'lamps'", "lights"});
  requireInputError("[[objects]]\ntype = \"sphear\"\nradius = 1\n", 2, {"unknown object type 'sphear'", "sphere"});
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"gold\"\n", 4,
                    {"unknown material 'gold'", "[materials.gold]"});
}

TEST_CASE("scene errors: wrong types") {
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = \"big\"\n", 3, {"'radius' must be a number", "string"});
  requireInputError(std::string("[[lights]]\nposition = [1, 2]\nintensity = 1\n") + kSphere, 2,
                    {"'position' must be an array of 3 numbers"});
  requireInputError(std::string("[options]\nwidth = 2.5\n") + kSphere, 2, {"'width' must be an integer"});
  requireInputError("[[objects]]\ntype = 3\n", 2, {"'type' must be a string"});
}

TEST_CASE("scene errors: missing fields") {
  requireInputError("[[objects]]\ntype = \"sphere\"\n", 1, {"missing key 'radius'"});
  requireInputError("[[objects]]\nradius = 1\n", 1, {"no 'type' key"});
  requireInputError(std::string("[[lights]]\nposition = [0, 1, 0]\n") + kSphere, 1, {"missing key 'intensity'"});
  requireInputError("[[objects]]\ntype = \"difference\"\n", 1, {"missing key 'children'"});
  requireInputError("[options]\nwidth = 3\n", 0, {"no objects", "[[objects]]"});
}

TEST_CASE("scene errors: NaN and infinity") {
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = nan\n", 3, {"finite"});
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = 1\ntranslate = [0, inf, 0]\n", 4, {"finite"});
}

TEST_CASE("scene errors: out-of-range values") {
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = -1\n", 3, {"'radius' must be > 0"});
  requireInputError("[[objects]]\ntype = \"hyperboloid\"\na = 1\nc = 1\nsheets = 3\n", 5, {"'sheets' must be 1 or 2"});
  requireInputError(std::string("[materials.m]\ndiffuse = [1, -1, 0]\n") + kSphere, 2, {"'diffuse' must be >= 0"});
  requireInputError("[[objects]]\ntype = \"difference\"\nchildren = [ { type = \"sphere\", radius = 1 } ]\n", 3,
                    {"at least 2 children"});
}

TEST_CASE("scene errors: singular and nearly singular transforms") {
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = 1\nscale = [1, 0, 1]\n", 4, {"singular", "scale"});
  requireInputError(
      "[[objects]]\ntype = \"sphere\"\nradius = 1\n"
      "matrix = [[1, 0, 0, 0], [1, 1e-12, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n",
      4, {"nearly singular"});
  requireInputError(
      "[[objects]]\ntype = \"sphere\"\nradius = 1\n"
      "matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 1, 0, 1]]\n",
      4, {"affine", "[0, 0, 0, 1]"});
  requireInputError("[[objects]]\ntype = \"sphere\"\nradius = 1\nrotate = { axis = [0, 0, 0], degrees = 5 }\n", 4,
                    {"non-zero"});
}

TEST_CASE("scene errors: a missing file names the file") {
  REQUIRE_THROWS_WITH(loadScene("/nonexistent/dir/scene.toml"),
                      Catch::Contains("/nonexistent/dir/scene.toml") && Catch::Contains("cannot read"));
}

TEST_CASE("scene: a format value extends the loader with node types and sections") {
  // A generator node: `count` spheres in a row, returned as one union; and a
  // section that defines the spacing, parsed before the objects. The
  // section's value lives in state the parsers share, not in the loader.
  auto spacing = std::make_shared<double>(1.0);
  SceneFormat format = builtinSceneFormat();
  format.addSection("test_rows", [spacing](const toml::node& section, ParseContext& ctx) {
    const toml::table* t = section.as_table();
    if (!t) ctx.fail(section, "test_rows must be a table");
    ctx.checkKeys(*t, {"spacing"});
    *spacing = ctx.requiredNumber(*t, "spacing");
  });
  format.addNodeType("test_row", [spacing](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"count"}, true);
    std::vector<NodeDesc> spheres;
    for (long long i = 0; i < ctx.integer(t, "count").value_or(1); ++i) {
      toml::table one{{"type", "sphere"}, {"radius", 0.25}};
      NodeDesc n = ctx.parseNode(one);
      n.transform[3] = glm::dvec4(*spacing * static_cast<double>(i), 0, 0, 1);
      spheres.push_back(std::move(n));
    }
    return NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(spheres), ctx.where(t));
  });
  const std::string text = "[test_rows]\nspacing = 2\n[[objects]]\ntype = \"test_row\"\ncount = 3\ntranslate = [0, 1, 0]\n";
  TempScene file(text);
  SceneDesc s = file.load(format);
  REQUIRE(s.root.children.size() == 3);
  REQUIRE(s.root.transform[3] == glm::dvec4(0, 1, 0, 1));
  REQUIRE(s.root.children[2].transform[3] == glm::dvec4(4, 0, 0, 1));
  // A key the generator does not know is still an error at its line.
  requireInputError("[test_rows]\nspacing = 2\n[[objects]]\ntype = \"test_row\"\ncuont = 3\n", 5,
                    {"unknown key 'cuont'", "count"}, format);
  // Nothing leaked into the loader: the built-in format knows neither.
  requireInputError(text, 1, {"unknown section 'test_rows'"});
}
