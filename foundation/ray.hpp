#pragma once
// A ray r(t) = origin + direction * t (thesis eq. 1.1). The direction is not
// necessarily unit length: transforming a ray into object space keeps t the
// same in both spaces, so hits from different leaves compare directly.
#include "foundation/vec.hpp"

namespace lattice {

template <typename T>
struct Ray {
  Vec3<T> origin{};
  Vec3<T> direction{};

  Vec3<T> at(T t) const { return origin + direction * t; }
  // The same ray in another space (t is preserved).
  Ray transformed(const Mat4<T>& m) const { return {transformPoint(m, origin), transformDirection(m, direction)}; }
};

}  // namespace lattice
