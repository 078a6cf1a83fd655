#pragma once
// The optical properties of a surface in the thesis's lighting model (eq. 2.3).
// Every coefficient is per RGB channel because the thesis evaluates (2.3) once
// per wavelength: k_amb, k_diff, k_spec and even n_spec may differ by channel.
#include <string>

#include "foundation/vec.hpp"

namespace lattice {

template <typename T>
struct Material {
  Vec3<T> ambient{T(0.2)};     // k_amb
  Vec3<T> diffuse{T(0.7)};     // k_diff
  Vec3<T> specular{T(0.0)};    // k_spec
  Vec3<T> shininess{T(10)};    // n_spec (Phong exponent)

  template <typename U>
  Material<U> cast() const {
    return {Vec3<U>(ambient), Vec3<U>(diffuse), Vec3<U>(specular), Vec3<U>(shininess)};
  }
};

// A material as named in a scene file; MaterialId is its index in the table.
struct NamedMaterial {
  std::string name;
  Material<double> material;
};

}  // namespace lattice
