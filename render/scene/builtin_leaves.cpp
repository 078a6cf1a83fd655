// The built-in leaves by name (render/scene/builtin_leaves.hpp): each the
// shape's leaf, built here once so callers need not include the template.
#include "render/scene/builtin_leaves.hpp"

#include "render/scene/shape_leaf.hpp"

namespace lattice {

LeafDescPtr makeQuarticLeafDesc(QuarticShape shape, std::string name) {
  return makeShapeLeaf(std::move(shape), std::move(name));
}
LeafDescPtr makeCapsuleLeafDesc(double radius, double length, std::string name) {
  return makeShapeLeaf(CapsuleShape{radius, length}, std::move(name));
}
LeafDescPtr makePolylineLeafDesc(std::vector<Vec3d> points, double radius) {
  return makeShapeLeaf(PolylineShape{std::move(points), radius});
}

}  // namespace lattice
