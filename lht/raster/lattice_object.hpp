#pragma once
// What a lattice is rasterized from: the exact object (the render module's
// quartics and CSG, traced in double), its tight bounding box, and a
// canonical text of its definition whose FNV-1a hash ties a .lht file to it.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lht/raster/object_cover.hpp"
#include "render/shapes/primitive.hpp"
#include "render/scene/scene.hpp"

namespace lattice::lht {

// The object as a union of parts that the cover's pieces hold one each
// (part k inside piece k): the rasterizer traces a segment against the parts
// it passes near (lht/raster/rasterize.hpp) instead of walking the union.
struct ObjectParts {
  std::shared_ptr<const Primitive<double>> owner;  // the union of the parts, which holds them
  std::vector<const Primitive<double>*> parts;
};

struct LatticeObject {
  std::string definition;  // canonical; equal definitions rasterize identically
  Bounds<double> bounds;   // tight box in object coordinates (sets the lattice size)
  std::shared_ptr<const Primitive<double>> primitive;  // object coordinates
  // Pieces containing the solid (object coordinates), for the rasterizer's
  // cull; unset: none known, every pair is traced.
  std::optional<ObjectCover> cover;
  // Set where the primitive is exactly the union of parts built by the same
  // call (a polyline's capsules), each inside its piece of `cover`; unset,
  // every segment is traced against the whole primitive.
  std::optional<ObjectParts> parts;
  std::uint64_t hash() const;
};

// A sphere of `radius` centred at the origin.
LatticeObject sphereObject(double radius);
// The thesis's "straight line": the segment (0,0,0)-(0,0,length) swept by a
// ball of `radius` (a capsule; its length excludes the round caps).
LatticeObject capsuleObject(double radius, double length);
// Spheres at `points` joined by cylinders of the same radius (the thesis's
// hook and hair: a union of capsules along a polyline).
LatticeObject polylineObject(const std::vector<Vec3d>& points, double radius, const std::string& name);
// A CSG subtree of a scene (its node transform included), described by
// `definition` (e.g. the TOML text it was parsed from).
LatticeObject sceneObject(const NodeDesc& node, std::string definition);

}  // namespace lattice::lht
