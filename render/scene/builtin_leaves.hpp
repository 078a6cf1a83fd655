#pragma once
// The built-in leaves by name, for a program that makes a scene without the
// scene loader and for the C++ a baked scene is (docs/firmware.md): a single
// quartic (thesis 3.2.1), a capsule (a sphere is one of length 0) and a
// polyline. Each is the shape's leaf (render/scene/shape_leaf.hpp); the names
// stay because baked scenes call them.
#include <string>
#include <vector>

#include "render/scene/scene.hpp"

namespace lattice {

LeafDescPtr makeQuarticLeafDesc(QuarticShape shape, std::string name);
LeafDescPtr makeCapsuleLeafDesc(double radius, double length, std::string name = "capsule");
// `type = "polyline"`: spheres at `points` joined by cylinders of `radius`.
LeafDescPtr makePolylineLeafDesc(std::vector<Vec3d> points, double radius);

}  // namespace lattice
