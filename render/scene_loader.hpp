#pragma once
// Scene files (TOML, docs/scene-format.md) -> SceneDesc.
//
// Two registries make the format extensible without touching the loader:
// * node types: `type = "sphere"` in [[objects]] (or in `children`) is looked
//   up in ONE table of NodeParser functions. render/node_types.cpp registers
//   the built-in shapes and set operations; other modules (lht/) add theirs
//   with registerNodeType("lattice", ...).
// * top-level sections: registerSection("lattices", ...) claims a section
//   the loader does not know. Registered sections are parsed after [options],
//   [materials.*], [camera] and [[lights]] and before [[objects]], in
//   registration order, so node parsers can use what a section defined.
//
// Registration must happen before loadScene() is called (e.g. from main or a
// module's init function); a static-library object that only registers
// itself from a static initializer may be dropped by the linker.
//
// Every mistake in a file is a lattice::Error(ErrorKind::Input) whose message
// starts "path:line:column:" and says what was expected.
#include <any>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "render/scene.hpp"

namespace lattice {

class ParseContext;

// Parses one object table (its own keys: the common keys type, material,
// translate, rotate, scale, matrix, name are handled by the loader) and
// returns the subtree it describes. A generator may return a union of many
// instances. The loader applies the table's transform and material on top.
using NodeParser = std::function<NodeDesc(const toml::table& table, ParseContext& context)>;
// Parses a registered top-level section (a table or an array of tables).
using SectionParser = std::function<void(const toml::node& section, ParseContext& context)>;

void registerNodeType(std::string type, NodeParser parser);
void registerSection(std::string name, SectionParser parser);
bool isNodeTypeRegistered(const std::string& type);

SceneDesc loadScene(const std::filesystem::path& file);
// Same, from text in memory; `fileName` is used in messages.
SceneDesc parseScene(std::string_view text, const std::filesystem::path& fileName);

// What parsers get: the file, the scene so far, checked accessors that throw
// located errors, and a place to keep per-load state of extension modules.
class ParseContext {
 public:
  ParseContext(std::filesystem::path file, SceneDesc& scene);

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
                 bool objectTable = false) const;

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

  // Per-load state of extension modules, keyed by module name.
  std::map<std::string, std::any>& extensions() { return extensions_; }

 private:
  std::filesystem::path file_;
  SceneDesc& scene_;
  std::map<std::string, std::any> extensions_;
  int depth_ = 0;  // nesting guard: a runaway recursion is an error, not a crash
};

}  // namespace lattice
