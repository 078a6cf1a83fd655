#pragma once
// Spheres at the points of a polyline joined by cylinders of the same radius
// - the thesis's hook (Figure 2) and hair (Plate 5) - built exactly as a
// union of capsules (render/shapes/composite_shapes.hpp).
#include <vector>

#include "render/shapes/primitive.hpp"
#include "render/scene/scene.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

// Throws lattice::Error(Input) for fewer than 2 points, coincident
// neighbours or a bad radius.
template <typename T>
PrimitivePtr<T> makePolyline(const std::vector<Vec3d>& points, double radius, const Mat4d& objectToWorld,
                             MaterialId material);

#define LATTICE_DECLARE(T) \
  extern template PrimitivePtr<T> makePolyline<T>(const std::vector<Vec3d>&, double, const Mat4d&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

// The exact box: every point grown by the radius.
Bounds<double> polylineBounds(const std::vector<Vec3d>& points, double radius);

// A scene leaf: `type = "polyline"`, `points = [[x, y, z], ...]`, `radius`.
LeafDescPtr makePolylineLeafDesc(std::vector<Vec3d> points, double radius);

}  // namespace lattice
