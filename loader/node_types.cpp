// The one table of object types a scene file can name. Each entry parses its
// own keys (the loader has already handled type, material and the transform)
// and returns a subtree: the set operations, the named presets of the quartic
// and capsule shapes (render/shapes/quartic_presets.hpp), and one entry per
// shape of render/shapes/leaf_shape.hpp, which reads its own keys through
// loader/shape_keys.hpp. A new shape adds nothing here.
#include "loader/node_types.hpp"

#include <fmt/format.h>

#include <functional>

#include "foundation/error.hpp"
#include "loader/shape_keys.hpp"
#include "render/scene/builtin_leaves.hpp"
#include "render/scene/shape_leaf.hpp"
#include "render/shapes/leaf_shape.hpp"
#include "render/shapes/quartic_presets.hpp"

namespace lattice {

namespace {

// Shape constructors report bad parameters without a position; add it.
NodeDesc quarticNode(const toml::table& t, ParseContext& ctx, const std::string& name,
                     const std::function<QuarticShape()>& make) {
  try {
    return NodeDesc::makeLeaf(makeQuarticLeafDesc(make(), name), ctx.where(t));
  } catch (const Error& e) {
    ctx.fail(t, fmt::format("{}: {}", name, e.what()));
  }
}

NodeParser setOperation(NodeDesc::Kind kind, std::size_t minChildren, const char* name) {
  return [=](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"children"}, true);
    std::vector<NodeDesc> children = ctx.parseChildren(t);
    if (children.size() < minChildren)
      ctx.fail(*t.get("children"), fmt::format("'{}' needs at least {} {}, got {}", name, minChildren,
                                               minChildren == 1 ? "child" : "children", children.size()));
    return NodeDesc::makeOperation(kind, std::move(children), ctx.where(t));
  };
}

// A shape of the table (render/shapes/leaf_shape.hpp) read by its own read().
template <typename Shape>
NodeDesc readShape(const toml::table& table, ParseContext& context) {
  context.checkKeys(table, Shape::kKeys, true);
  ShapeKeys keys(table, context);
  return NodeDesc::makeLeaf(makeShapeLeaf(Shape::read(keys)), context.where(table));
}

}  // namespace

std::map<std::string, NodeParser> builtinNodeTypes() {
  std::map<std::string, NodeParser> types;
  types["union"] = setOperation(NodeDesc::Kind::Union, 1, "union");
  types["intersection"] = setOperation(NodeDesc::Kind::Intersection, 1, "intersection");
  types["difference"] = setOperation(NodeDesc::Kind::Difference, 2, "difference");

  types["sphere"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"radius"}, true);
    const double r = ctx.positiveNumber(t, "radius");
    // The same solid as the quartic x^2 + y^2 + z^2 = r^2 (which fixed point
    // still builds), solved in closed form in float and double.
    return NodeDesc::makeLeaf(makeCapsuleLeafDesc(r, 0.0, "sphere"), ctx.where(t));
  };
  types["ellipsoid"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"radii"}, true);
    const Vec3d r = ctx.requiredVec3(t, "radii");
    return quarticNode(t, ctx, "ellipsoid", [&] { return ellipsoid(r.x, r.y, r.z); });
  };
  types["cylinder"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"radius"}, true);
    const double r = ctx.positiveNumber(t, "radius");
    return quarticNode(t, ctx, "cylinder", [&] { return cylinder(r); });
  };
  types["cone"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"slope"}, true);
    const double s = ctx.positiveNumber(t, "slope");
    return quarticNode(t, ctx, "cone", [&] { return cone(s); });
  };
  types["paraboloid"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"k"}, true);
    const double k = ctx.positiveNumber(t, "k");
    return quarticNode(t, ctx, "paraboloid", [&] { return paraboloid(k); });
  };
  types["hyperboloid"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"a", "c", "sheets"}, true);
    const double a = ctx.positiveNumber(t, "a"), c = ctx.positiveNumber(t, "c");
    const long long sheets = ctx.integer(t, "sheets").value_or(1);
    if (sheets != 1 && sheets != 2) ctx.fail(*t.get("sheets"), "'sheets' must be 1 or 2");
    return quarticNode(t, ctx, "hyperboloid", [&] { return hyperboloid(a, c, sheets == 1); });
  };
  types["torus"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"major", "minor"}, true);
    const double R = ctx.positiveNumber(t, "major"), r = ctx.positiveNumber(t, "minor");
    return quarticNode(t, ctx, "torus", [&] { return torus(R, r); });
  };
  types["half_space"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"normal", "offset"}, true);
    const Vec3d n = ctx.requiredVec3(t, "normal");
    const double offset = ctx.number(t, "offset").value_or(0.0);
    return quarticNode(t, ctx, "half_space", [&] { return halfSpace(n, offset); });
  };
  // Every shape of the table the loader reads itself (the lattice's type
  // comes with the lattice module: loader/lattice_scene_loader.cpp).
  forEachShape([&]<typename Shape>() {
    if constexpr (requires(ShapeKeys& keys) { Shape::read(keys); }) types[std::string(Shape::kName)] = readShape<Shape>;
  });
  return types;
}

}  // namespace lattice
