#pragma once
// A cover of a lattice's object: capsules and boxes whose union contains the
// solid, so the rasterizer can call a segment that stays clear of every piece
// a miss without tracing it (lht/raster/cover_cull.hpp). Nothing here is traced: the
// object's exact primitive still answers every pair that may touch it.
//
// Method: from the scene description (render/shapes/leaf_shape.hpp), not from the
// built primitive. A shape that states its balls (a capsule, a polyline) gives
// their capsules, a sphere the capsule of length 0, any other leaf (quartics, lattices, leaf types
// that do not say what they are) its box; a union covers with all its
// operands' pieces, an intersection with the operand whose cover is
// smallest, a difference with its first operand. A transform maps a capsule
// to the capsule between the mapped end points whose radius is the old one
// times a bound on the map's largest stretch (exact for a similarity, larger
// otherwise), so the cover stays a superset under any affine map.
#include <vector>

#include "foundation/bounds.hpp"
#include "foundation/vec.hpp"

namespace lattice {
struct NodeDesc;
}

namespace lattice::lht {

// The segment from a to b swept by a ball of `radius`.
struct CoverCapsule {
  Vec3d a{0.0}, b{0.0};
  double radius = 0.0;
};

struct ObjectCover {
  std::vector<CoverCapsule> capsules;
  std::vector<Bounds<double>> boxes;  // finite; an infinite piece makes the cover `unbounded`
  bool unbounded = false;             // no use for culling: every segment may touch the object

  // The cover of the image of the solid under `m` (an affine map).
  ObjectCover mapped(const Mat4d& m) const;
  void add(const ObjectCover& other);
  // A size to choose between an intersection's operands: the sum of the
  // pieces' box volumes (infinite when unbounded).
  double volume() const;
};

// The cover of a scene subtree in the coordinates `parentToObject` maps its
// parent's coordinates to (the node's own transform is applied inside).
ObjectCover coverOf(const NodeDesc& node, const Mat4d& parentToObject);

// The capsules of a polyline (spheres at the points joined by cylinders).
ObjectCover polylineCover(const std::vector<Vec3d>& points, double radius);

}  // namespace lattice::lht
