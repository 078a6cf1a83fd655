#pragma once
// A half-space (a quartic of degree 1: a . x + a0 < 0 inside, such as the
// scenes' `half_space` floors) as one leaf with a closed-form crossing, for
// the floating arithmetics (closed-form leaves where a shape has them, the
// general quartic kept for what needs it). Fixed point keeps the quartic leaf.
//
// Method: the object-space plane is carried to the world once, at build time
// (N = A^-T a, c = a0 - N . b for objectToWorld = (A, b), both divided by
// |N|), so a ray costs two dot products and a division: f(o + t d) =
// (N . o + c) + t (N . d). The answers are the quartic leaf's (render/shapes/quartic.cpp)
// case by case: a ray parallel to the plane is inside along its whole line
// when f(o) < 0 and crosses nothing otherwise; the unbounded end of the span
// has t = +-inf and a zero normal; the world normal is computed from the
// gradient exactly as the quartic leaf computes it, so it is the same to the
// bit. Only t differs in the last bits (the quartic leaf solves for it
// about the point of the ray nearest the origin, in unit steps).
//
// Tunables: none.
#include "render/shapes/primitive.hpp"
#include "render/shapes/quartic.hpp"

namespace lattice {

// f must have degree 1. Bounds and refusals are the quartic leaf's
// (makeQuarticLeaf) for the same f, bounds and transform. Float and double only.
template <typename T>
PrimitivePtr<T> makePlaneLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds,
                              const Mat4d& objectToWorld, MaterialId material);

}  // namespace lattice
