// The table of shapes (render/shapes/leaf_shape.hpp) and the scene loader
// agree: every row has a name of its own, the loader reads an object of each
// row's `type` from the row's example keys, and the leaf it makes says it is
// that row's shape and no other. Here, in the lattice suite, because the
// lattice row's type comes with the lattice module
// (loader/lattice_scene_loader.hpp), which this suite links.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "loader/lattice_scene_loader.hpp"
#include "loader/scene_loader.hpp"
#include "render/shapes/leaf_shape.hpp"

using namespace lattice;

namespace {

// Every row's name, in the table's order.
std::vector<std::string_view> rowNames() {
  std::vector<std::string_view> names;
  forEachShape([&]<typename Shape>() { names.push_back(Shape::kName); });
  return names;
}

}  // namespace

TEST_CASE("shape table: one row per alternative, each with a name of its own") {
  const std::vector<std::string_view> names = rowNames();
  CHECK(names.size() == std::variant_size_v<LeafShape>);
  const std::set<std::string_view> unique(names.begin(), names.end());
  CHECK(unique.size() == names.size());
  for (std::string_view name : names) CHECK_FALSE(name.empty());
}

TEST_CASE("shape table: the loader reads each row's type back as that row's shape") {
  // The lattice row's example names this definition.
  std::string text = "[[lattices]]\nname = \"example\"\nspacing = 0.1\nobject = { type = \"sphere\", radius = 0.5 }\n\n";
  forEachShape([&]<typename Shape>() {
    text += fmt::format("[[objects]]\ntype = \"{}\"\n{}\n\n", Shape::kName, Shape::kExample);
  });
  const SceneDesc scene = lht::parseSceneWithLattices(text, "shapes.toml").scene;
  const std::vector<std::string_view> names = rowNames();
  REQUIRE(scene.root.children.size() == names.size());
  for (std::size_t row = 0; row < names.size(); ++row) {
    INFO("row " << row << ", type \"" << names[row] << "\"");
    const NodeDesc& node = scene.root.children[row];
    REQUIRE(node.kind == NodeDesc::Kind::Leaf);
    const std::optional<LeafShape> shape = node.leaf->shape();
    REQUIRE(shape.has_value());
    CHECK(shape->index() == row);
    CHECK(shapeName(*shape) == names[row]);
  }
}

TEST_CASE("shape table: the built-in format reads every row but the lattice, which its module adds") {
  const SceneFormat builtin = builtinSceneFormat();
  for (std::string_view name : rowNames()) {
    INFO(name);
    CHECK(builtin.nodeTypes.contains(std::string(name)) == (name != LatticeShape::kName));
  }
}
