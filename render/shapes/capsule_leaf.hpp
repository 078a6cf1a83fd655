#pragma once
// A capsule as one leaf with closed-form intersections (closed-form leaves
// where a shape has them, the general quartic kept for what needs it), for the
// floating arithmetics. Fixed point keeps the quartic-and-CSG capsule of
// composite_shapes.cpp, whose range checks it relies on.
//
// Method: the capsule is convex, so a line crosses it in one interval, and
// that interval is the union of the line's intervals through its three convex
// parts (the body, the infinite cylinder between the end planes, and the two
// end balls). Each part's interval comes from a quadratic solved about the
// point of the line nearest the part's axis or centre, so the discriminant is
// r^2 - distance^2 between numbers of the radius's size rather than a
// difference of squares of the ray origin's distance (the float arithmetic
// needs this for hairs 0.006 wide seen from 5 units away).
//
// Tunables: none. A body interval that starts or ends on an end plane is cut
// short by that plane, which lies inside the end ball, so the ball's interval
// decides that end (and its normal).
#include "render/shapes/primitive.hpp"
#include "foundation/bounds.hpp"
#include "foundation/vec.hpp"

namespace lattice {

// The segment from (0,0,0) to (0,0,length) in object space swept by a ball of
// `radius`, placed by objectToWorld, with its world box (grown by the caller
// for rounding). Only for float and double. Throws lattice::Error (Input) for
// a transform a quartic leaf would refuse (non-finite, ill-conditioned).
template <typename T>
PrimitivePtr<T> makeCapsuleLeaf(double radius, double length, const Mat4d& objectToWorld, const Bounds<T>& worldBox,
                                MaterialId material);

}  // namespace lattice
