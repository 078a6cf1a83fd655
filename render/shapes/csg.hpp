#pragma once
// Constructive solid geometry nodes (thesis 3.1 after [Requicha 1980]): a
// node merges the span lists of its children. Nodes are n-ary:
//   Union        - inside any child
//   Intersection - inside every child
//   Difference   - inside the first child and outside all the others
// Normals always point out of the result: a span end that comes from a
// subtracted solid has its normal flipped. A span end keeps the material of
// the surface that produced it.
//
// Unions with many children keep them in a bounding volume hierarchy
// (render/accel/wide_bvh.hpp for float and double, render/accel/bvh.hpp for fixed point),
// so a union of thousands of hairs costs about log N per ray.
//
// anyHit (shadow rays) of a union stops at the first child crossing found. A
// child crossing is a crossing of the union except when the union covers the
// whole segment (tmin, tmax); such a segment is inside the solid, so it is
// blocked either way. Intersections and differences answer exactly.
#include <vector>

#include "render/shapes/primitive.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

enum class CsgOp { Union, Intersection, Difference };

// Throws lattice::Error (Input) for no children or a null child. `threads`:
// a union's BVH is built on up to this many (the same tree at every count).
template <typename T>
PrimitivePtr<T> makeCsgNode(CsgOp op, std::vector<PrimitivePtr<T>> children, unsigned threads = 1);

// The same, with a box the caller knows contains the result (for example a
// capsule, whose cylinder and half-spaces are all unbounded once rotated):
// the node's box is the computed box intersected with `limit`.
template <typename T>
PrimitivePtr<T> makeCsgNode(CsgOp op, std::vector<PrimitivePtr<T>> children, const Bounds<T>& limit);

#define LATTICE_DECLARE(T) \
  extern template PrimitivePtr<T> makeCsgNode<T>(CsgOp, std::vector<PrimitivePtr<T>>, unsigned); \
  extern template PrimitivePtr<T> makeCsgNode<T>(CsgOp, std::vector<PrimitivePtr<T>>, const Bounds<T>&);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
