#pragma once
// A quadric (a quartic of degree 2: the scenes' cylinder, ellipsoid, cone,
// paraboloid, hyperboloid) as one leaf with closed-form crossings, for the
// floating arithmetics (closed-form leaves where a shape has them, the general
// quartic kept for what needs it). Fixed point keeps the quartic leaf.
//
// Method: f(x) = x.A x + b.x + c with A symmetric, taken from the quartic's
// coefficients once. The ray is carried to object space and re-based at its
// point nearest the object box's middle, with a unit direction, exactly as the
// quartic leaf does (QuarticArithmetic::toObject), so the quadratic's
// coefficients are of the object's size; its roots come from the stable
// formula (q = -(b + sign(b) sqrt(disc)) / 2, roots q / a and c / q), not the
// general solver with its polishing. Inside and outside follow the quartic
// leaf's rule: the sign of the leading coefficient at the ends of the line
// (a < 0: inside outside the roots, two unbounded spans); a line without
// two distinct roots (disc <= 0) has the sign of a throughout, a touching
// point (disc = 0) splitting an inside line in two; normals are the gradient
// 2 A x + b through the normal matrix, facing the ray where it vanishes (a
// cone's apex).
//
// Tunables: none.
#include "render/shapes/primitive.hpp"
#include "render/shapes/quartic.hpp"

namespace lattice {

// f must have degree 2. Bounds and refusals are the quartic leaf's
// (makeQuarticLeaf) for the same f, bounds and transform. Float and double only.
template <typename T>
PrimitivePtr<T> makeQuadricLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds,
                                const Mat4d& objectToWorld, MaterialId material);

}  // namespace lattice
