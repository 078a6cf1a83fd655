#pragma once
// An instance: one object-space primitive shared by many placements (a
// two-level structure: a top BVH over instances, one shared structure per
// object). The scatter's union of instances is the top level; each
// instance carries the ray into its object's space and the hit back.
//
// Method: a precomputed affine world-to-object map (3x4) takes the ray's
// origin and direction to object space without normalising the direction, so
// t is the same in both spaces and the object's t values are returned as they
// are; normals go back by the inverse transpose of the linear part and are
// normalised. The world box is what placedBounds() finds for the object's
// description (per ball for polylines and capsules, so a bent hair gets the
// box its world-space copy had, not its object box turned), grown for
// rounding to T. The instance does not clip its own box: its parent, the
// union's BVH, has just done so, and the object's root clips in object space. Only for float and double: fixed point keeps one
// world-space copy per instance (docs/fixed-point.md: its transforms are
// checked leaf by leaf, and two maps in a row would lose bits of Q31.32).
//
// Tunables: none.
#include <memory>

#include "render/shapes/primitive.hpp"
#include "foundation/bounds.hpp"
#include "foundation/vec.hpp"

namespace lattice {

template <typename T>
using SharedPrimitive = std::shared_ptr<const Primitive<T>>;

struct NodeDesc;

// `object` placed in the world by objectToWorld (affine, invertible), inside
// `worldBox` (from placedBounds). Throws lattice::Error (Input) for a
// transform a leaf would refuse.
template <typename T>
PrimitivePtr<T> makeInstance(SharedPrimitive<T> object, const Mat4d& objectToWorld, const Bounds<double>& worldBox);

// A world box holding the solid `object` describes, placed by objectToWorld:
// polylines and capsules boxed ball by ball, other leaves by their object box
// through its eight corners; unions and intersections by the union of their
// operands' boxes, differences by their first operand's.
Bounds<double> placedBounds(const NodeDesc& object, const Mat4d& objectToWorld);

}  // namespace lattice
