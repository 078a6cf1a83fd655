#pragma once
// Point light sources of eq. 2.3. `intensity` is the thesis's I_inc per RGB
// channel; the renderer divides it by (D_i + K), D_i the distance from the
// light to the lit point and K the scene-wide constant that softens the
// inverse law (thesis sec. 2.4). So I_inc is the intensity a point at
// distance 1 - K would receive; with K = 0 a light of intensity 10 at
// distance 10 delivers 1.
#include "foundation/vec.hpp"

namespace lattice {

template <typename T>
struct PointLight {
  Vec3<T> position{};
  Vec3<T> intensity{T(1)};

  template <typename U>
  PointLight<U> cast() const {
    return {Vec3<U>(position), Vec3<U>(intensity)};
  }
};

}  // namespace lattice
