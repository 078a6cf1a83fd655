// The one table of object types a scene file can name. Each entry parses its
// own keys (the loader has already handled type, material and the transform)
// and returns a subtree. Shapes come from render/shapes/quartic_presets.hpp and
// render/shapes/composite_shapes.hpp; this file only maps TOML onto them.
#include "loader/node_types.hpp"

#include <fmt/format.h>

#include <cctype>
#include <functional>

#include "render/shapes/composite_shapes.hpp"
#include "render/scene/builtin_leaves.hpp"
#include "render/scene/polyline.hpp"
#include "render/shapes/quartic.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "foundation/error.hpp"

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

// "x2y1z0" -> (2, 1, 0); every letter present once, in order.
bool parseMonomial(std::string_view key, int& i, int& j, int& k) {
  if (key.size() != 6 || key[0] != 'x' || key[2] != 'y' || key[4] != 'z') return false;
  for (std::size_t p : {1u, 3u, 5u})
    if (!std::isdigit(static_cast<unsigned char>(key[p]))) return false;
  i = key[1] - '0';
  j = key[3] - '0';
  k = key[5] - '0';
  return i + j + k <= QuarticPolynomial::kMaxDegree;
}

NodeDesc parseQuartic(const toml::table& t, ParseContext& ctx) {
  ctx.checkKeys(t, {"coefficients", "bounds"}, true);
  const toml::node* c = t.get("coefficients");
  if (!c) ctx.fail(t, "missing key 'coefficients' (a table like { x2y0z0 = 1, x0y0z0 = -1 } or a list of 35 numbers)");
  QuarticPolynomial f;
  if (const toml::table* terms = c->as_table()) {
    for (auto&& [key, value] : *terms) {
      int i = 0, j = 0, k = 0;
      if (!parseMonomial(key.str(), i, j, k))
        ctx.fail(value, fmt::format("coefficient key '{}' is not of the form x<i>y<j>z<k> with i + j + k <= 4 "
                                    "(e.g. x2y0z0 for x^2, x0y0z0 for the constant)",
                                    key.str()));
      f.addTerm(ctx.toNumber(value, key.str()), i, j, k);
    }
  } else if (const toml::array* list = c->as_array()) {
    if (list->size() != QuarticPolynomial::kTerms)
      ctx.fail(*c, fmt::format("'coefficients' as a list must have {} numbers (got {}), ordered by total degree: "
                               "1, x, y, z, x^2, xy, xz, y^2, yz, z^2, x^3, ...",
                               QuarticPolynomial::kTerms, list->size()));
    for (int n = 0; n < QuarticPolynomial::kTerms; ++n)
      f.a[static_cast<std::size_t>(n)] = ctx.toNumber((*list)[static_cast<std::size_t>(n)], "coefficients");
  } else {
    ctx.fail(*c, "'coefficients' must be a table of x<i>y<j>z<k> keys or a list of 35 numbers");
  }
  if (f.degree() < 1) ctx.fail(*c, "a quartic needs at least one non-constant term (f = constant has no surface)");
  Bounds<double> bounds = Bounds<double>::infinite();
  if (const toml::node* b = t.get("bounds")) {
    const toml::table* bt = b->as_table();
    if (!bt) ctx.fail(*b, "'bounds' must be a table { min = [x, y, z], max = [x, y, z] } containing the solid");
    ctx.checkKeys(*bt, {"min", "max"});
    bounds = {ctx.requiredVec3(*bt, "min"), ctx.requiredVec3(*bt, "max")};
    if (bounds.empty()) ctx.fail(*b, "'bounds' min must be <= max in every coordinate");
  }
  return NodeDesc::makeLeaf(makeQuarticLeafDesc(QuarticShape{f, bounds}, "quartic"), ctx.where(t));
}

// Spheres joined by cylinders along a path (the thesis's hook and hair).
NodeDesc parsePolyline(const toml::table& table, ParseContext& context) {
  context.checkKeys(table, {"points", "radius"}, true);
  const double radius = context.positiveNumber(table, "radius");
  const toml::array* list = table.get("points") ? table.get("points")->as_array() : nullptr;
  if (!list || list->size() < 2)
    context.fail(table, "a polyline needs `points = [[x, y, z], [x, y, z], ...]` with at least two points");
  std::vector<Vec3d> points;
  for (const toml::node& p : *list) points.push_back(context.toVec3(p, "a polyline point"));
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i] == points[i - 1]) context.fail((*list)[i], "this polyline point repeats the one before it");
  return NodeDesc::makeLeaf(makePolylineLeafDesc(std::move(points), radius), context.where(table));
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
  types["capsule"] = [](const toml::table& t, ParseContext& ctx) {
    ctx.checkKeys(t, {"radius", "length"}, true);
    const double r = ctx.positiveNumber(t, "radius");
    const double length = ctx.number(t, "length").value_or(0.0);
    if (length < 0) ctx.fail(*t.get("length"), "'length' of a capsule must be >= 0");
    return NodeDesc::makeLeaf(makeCapsuleLeafDesc(r, length), ctx.where(t));
  };
  types["polyline"] = parsePolyline;
  types["quartic"] = parseQuartic;
  return types;
}

}  // namespace lattice
