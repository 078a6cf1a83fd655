#pragma once
// Scene files (TOML, docs/scene-format.md) -> SceneDesc.
//
// What a file may say is a value, a SceneFormat, handed to the loader; there
// is no global registry. builtinSceneFormat() holds the built-in shapes and
// set operations (loader/node_types.cpp). A module above render/ extends a
// copy: lht/ adds the [[lattices]] section and the lattice object types
// (loader/lattice_scene_loader.hpp), with parsers that keep what one load defines in
// state they own, so the load returns the scene and the lattices together.
// * node types: `type = "sphere"` in [[objects]] (or in `children`) is looked
//   up in the format's table of NodeParser functions.
// * top-level sections: a SectionParser claims a section the loader does not
//   know. Sections are parsed after [options], [materials.*], [camera] and
//   [[lights]] and before [[objects]], in the order they were added, so node
//   parsers can use what a section defined.
//
// Every mistake in a file is a lattice::Error(ErrorKind::Input) whose message
// starts "path:line:column:" and says what was expected.
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "render/scene/scene.hpp"

namespace lattice {

class ParseContext;

// Parses one object table (its own keys: the common keys type, material,
// translate, rotate, scale, matrix, name are handled by the loader) and
// returns the subtree it describes. A generator may return a union of many
// instances. The loader applies the table's transform and material on top.
using NodeParser = std::function<NodeDesc(const toml::table& table, ParseContext& context)>;
// Parses a registered top-level section (a table or an array of tables).
using SectionParser = std::function<void(const toml::node& section, ParseContext& context)>;

// The object types and extra sections a scene file may use.
struct SceneFormat {
  std::map<std::string, NodeParser> nodeTypes;
  std::vector<std::pair<std::string, SectionParser>> sections;  // in parsing order

  // Adds or replaces a type; adds a section (replacing one of that name in place).
  void addNodeType(std::string type, NodeParser parser);
  void addSection(std::string name, SectionParser parser);
};

// The built-in shapes and set operations, no extra sections.
SceneFormat builtinSceneFormat();

SceneDesc loadScene(const std::filesystem::path& file, const SceneFormat& format = builtinSceneFormat());
// Same, from text in memory; `fileName` is used in messages.
SceneDesc parseScene(std::string_view text, const std::filesystem::path& fileName,
                     const SceneFormat& format = builtinSceneFormat());

// What parsers get: the file, the scene so far, and checked accessors that
// throw located errors.
class ParseContext {
 public:
  ParseContext(std::filesystem::path file, SceneDesc& scene, const SceneFormat& format);

  const std::filesystem::path& file() const { return file_; }
  SceneDesc& scene() { return scene_; }
  const SceneDesc& scene() const { return scene_; }

  // "file:line:col" of a node (just "file" when toml++ has no position).
  std::string where(const toml::node& node) const;
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const;
  [[noreturn]] void fail(const toml::source_region& region, const std::string& message) const;

  // Unknown keys are errors. `allowed` lists the keys this table may have
  // besides, for object tables, the common node keys.
  void checkKeys(const toml::table& table, std::initializer_list<std::string_view> allowed,
                 bool objectTable = false) const {
    checkKeys(table, std::span<const std::string_view>(allowed.begin(), allowed.size()), objectTable);
  }
  void checkKeys(const toml::table& table, std::span<const std::string_view> allowed, bool objectTable = false) const;

  // Typed, located accessors. `required*` fail when the key is missing; the
  // others return nullopt. Numbers must be finite (integers are accepted).
  std::optional<double> number(const toml::table& table, std::string_view key) const;
  double requiredNumber(const toml::table& table, std::string_view key) const;
  double positiveNumber(const toml::table& table, std::string_view key) const;  // required, > 0
  std::optional<long long> integer(const toml::table& table, std::string_view key) const;
  std::optional<bool> boolean(const toml::table& table, std::string_view key) const;
  std::optional<std::string> string(const toml::table& table, std::string_view key) const;
  std::optional<Vec3d> vec3(const toml::table& table, std::string_view key) const;  // [x, y, z]
  Vec3d requiredVec3(const toml::table& table, std::string_view key) const;
  // A colour: [r, g, b] or one number for grey; each channel >= 0.
  std::optional<Vec3d> color(const toml::table& table, std::string_view key) const;
  double toNumber(const toml::node& node, std::string_view what) const;
  Vec3d toVec3(const toml::node& node, std::string_view what) const;

  // A material name -> MaterialId (error naming the known materials if unknown).
  MaterialId material(const toml::node& nameNode) const;

  // The transform described by a table's translate/rotate/scale/matrix keys
  // (identity if none). Order: scale, then rotate, then translate; `matrix`
  // (4 rows of 4, last row 0 0 0 1) excludes the others. Singular or nearly
  // singular results are errors.
  Mat4d transform(const toml::table& table) const;
  // A whole object table (type lookup, transform, material) -> NodeDesc.
  // Node parsers call it for nested children.
  NodeDesc parseNode(const toml::node& objectNode);
  // `children = [ {...}, ... ]` of a set operation.
  std::vector<NodeDesc> parseChildren(const toml::table& table, std::string_view key = "children");

 private:
  std::filesystem::path file_;
  SceneDesc& scene_;
  const SceneFormat& format_;
  int depth_ = 0;  // nesting guard: a runaway recursion is an error, not a crash
};

}  // namespace lattice
