#include "lht/raster/lattice_object.hpp"

#include <fmt/format.h>

#include <cmath>

#include "foundation/fnv1a.hpp"
#include "render/shapes/composite_shapes.hpp"
#include "render/shapes/polyline_parts.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

// A box around a CSG subtree from its leaves' own boxes. The built tree's
// bounds() would do, but a rotated leaf's box is the box of its rotated box;
// taking each leaf's box through its full transform is no tighter, so the
// gain here is in set operations (an intersection keeps the overlap).
Bounds<double> nodeBounds(const NodeDesc& node, const Mat4d& parentToObject) {
  const Mat4d toObject = parentToObject * node.transform;
  if (node.kind == NodeDesc::Kind::Leaf)
    return node.leaf ? transformBounds(node.leaf->objectBounds(), toObject) : Bounds<double>{};
  Bounds<double> box;
  if (node.children.empty()) return box;
  if (node.kind == NodeDesc::Kind::Union) {
    for (const NodeDesc& child : node.children) box.extend(nodeBounds(child, toObject));
  } else if (node.kind == NodeDesc::Kind::Intersection) {
    box = nodeBounds(node.children.front(), toObject);
    for (std::size_t i = 1; i < node.children.size(); ++i) {
      const Bounds<double> other = nodeBounds(node.children[i], toObject);
      box.lo = glm::max(box.lo, other.lo);
      box.hi = glm::min(box.hi, other.hi);
    }
  } else {
    box = nodeBounds(node.children.front(), toObject);  // a difference lies inside its first operand
  }
  return box;
}

// A polyline leaf's capsules, built as buildPrimitive builds its union (the
// leaf's shape with the node's transform), in the order coverOf gives their
// capsules; nothing for any other node.
std::optional<ObjectParts> polylineParts(const NodeDesc& node) {
  if (node.kind != NodeDesc::Kind::Leaf || !node.leaf) return std::nullopt;
  const std::optional<LeafShape> shape = node.leaf->shape();
  const PolylineShape* polyline = shape ? std::get_if<PolylineShape>(&*shape) : nullptr;
  if (!polyline) return std::nullopt;
  ObjectParts parts;
  parts.owner = makePolylineNamingParts<double>(polyline->points, polyline->radius, Mat4d(1.0) * node.transform,
                                                node.material.value_or(0), parts.parts);
  return parts;
}

}  // namespace

std::uint64_t LatticeObject::hash() const { return fnv1a64(definition); }

LatticeObject sphereObject(double radius) {
  const QuarticShape shape = sphere(radius);  // validates radius
  LatticeObject object;
  object.definition = fmt::format("sphere radius={:.17g}", radius);
  object.bounds = {Vec3d(-radius), Vec3d(radius)};
  object.primitive = makeQuarticLeaf<double>(shape.f, shape.bounds, Mat4d(1.0), 0);
  object.cover = polylineCover({Vec3d(0.0)}, radius);
  return object;
}

LatticeObject capsuleObject(double radius, double length) {
  LatticeObject object;
  object.primitive = makeCapsule<double>(radius, length, Mat4d(1.0), 0);  // validates
  object.definition = fmt::format("capsule radius={:.17g} length={:.17g}", radius, length);
  object.bounds = {Vec3d(-radius, -radius, -radius), Vec3d(radius, radius, length + radius)};
  object.cover = polylineCover({Vec3d(0.0), Vec3d(0.0, 0.0, length)}, radius);
  return object;
}

LatticeObject polylineObject(const std::vector<Vec3d>& points, double radius, const std::string& name) {
  LatticeObject object;
  object.definition = fmt::format("polyline '{}' radius={:.17g}", name, radius);
  for (const Vec3d& p : points) object.definition += fmt::format(" ({:.17g},{:.17g},{:.17g})", p.x, p.y, p.z);
  ObjectParts parts;
  try {
    parts.owner = makePolylineNamingParts<double>(points, radius, Mat4d(1.0), 0, parts.parts);
  } catch (const Error& e) {
    throw Error(e.kind(), fmt::format("{}: {}", name, e.what()));
  }
  object.primitive = parts.owner;
  object.bounds = polylineBounds(points, radius);
  object.cover = polylineCover(points, radius);
  object.parts = std::move(parts);
  return object;
}

LatticeObject sceneObject(const NodeDesc& node, std::string definition) {
  BuildOptions options;
  options.fullRayTrace = true;  // a lattice inside a lattice object is traced exactly
  LatticeObject object;
  object.primitive = buildPrimitive<double>(node, Mat4d(1.0), options);
  // Both boxes contain the solid, so their overlap does too.
  const Bounds<double> built = object.primitive->bounds();
  object.bounds = nodeBounds(node, Mat4d(1.0));
  object.bounds.lo = glm::max(object.bounds.lo, built.lo);
  object.bounds.hi = glm::min(object.bounds.hi, built.hi);
  object.cover = coverOf(node, Mat4d(1.0));
  object.parts = polylineParts(node);
  object.definition = std::move(definition);
  return object;
}

}  // namespace lattice::lht
