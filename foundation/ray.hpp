#pragma once
// A ray r(t) = origin + direction * t (thesis eq. 1.1). The direction is not
// necessarily unit length: transforming a ray into object space keeps t the
// same in both spaces, so hits from different leaves compare directly.
//
// The box tests (Bounds::clip, the BVH's SlabTest) multiply by 1 / direction.
// A world ray meets several boxes with the same direction (the root union's,
// its BVH's, each quartic leaf's, the scatter's and its BVH's), so in fixed
// point, where that quotient is a long division in software (the firmware,
// docs/firmware.md), the ray keeps it once computed: inverseDirection() gives
// the same bits as T(1) / direction, computed at most once a ray. In float
// and double, a hardware division, nothing is kept and the ray stays two
// vectors.
#include "foundation/vec.hpp"

namespace lattice {

// What a ray keeps of its reciprocal direction: nothing for IEEE types.
template <typename T, bool kKept = !kIsIeee<T>>
struct KeptInverse {};
template <typename T>
struct KeptInverse<T, true> {
  Vec3<T> inverse;
  bool known = false;
};

template <typename T>
struct Ray {
  Vec3<T> origin{};
  Vec3<T> direction{};
  // Written only by inverseDirection(); a ray's direction is not changed
  // after its first box test (none is: rays are made, never edited).
  [[no_unique_address]] mutable KeptInverse<T> kept{};

  Vec3<T> at(T t) const { return origin + direction * t; }
  // The same ray in another space (t is preserved).
  Ray transformed(const Mat4<T>& m) const { return {transformPoint(m, origin), transformDirection(m, direction)}; }
  // T(1) / direction (a zero component's as T divides by zero), and one
  // component of it.
  Vec3<T> inverseDirection() const {
    if constexpr (kIsIeee<T>) return T(1) / direction;
    else return keptInverse();
  }
  T inverseDirection(int axis) const {
    if constexpr (kIsIeee<T>) return T(1) / direction[axis];
    else return keptInverse()[axis];
  }

 private:
  const Vec3<T>& keptInverse() const {
    if (!kept.known) {
      kept.inverse = T(1) / direction;
      kept.known = true;
    }
    return kept.inverse;
  }
};

}  // namespace lattice
