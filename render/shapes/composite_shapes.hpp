#pragma once
// Exact composite shapes built from quartics with CSG, used by lattice
// rasterization and scenes.
#include "render/shapes/csg.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

// A capsule: the segment from (0,0,0) to (0,0,length) in object space swept
// by a ball of `radius`, as (cylinder ∩ z >= 0 ∩ z <= length) ∪ two end
// spheres, placed by objectToWorld. length may be 0 (a sphere). Float and
// double get one closed-form leaf (capsule_leaf.hpp), fixed point the quartics.
// Throws lattice::Error (Input) for radius <= 0, length < 0 or non-finite values.
template <typename T>
PrimitivePtr<T> makeCapsule(double radius, double length, const Mat4d& objectToWorld, MaterialId material);

// The same capsule as quartic leaves joined by CSG, in every arithmetic: what
// fixed point renders, and the reference the closed form is tested against.
template <typename T>
PrimitivePtr<T> makeQuarticCapsule(double radius, double length, const Mat4d& objectToWorld, MaterialId material);

#define LATTICE_DECLARE(T)                                                                      \
  extern template PrimitivePtr<T> makeCapsule<T>(double, double, const Mat4d&, MaterialId); \
  extern template PrimitivePtr<T> makeQuarticCapsule<T>(double, double, const Mat4d&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
