#pragma once
// Vector and matrix types of the per-pixel path. The scalar T is a template
// parameter everywhere on that path (float and double now; a fixed-point
// type later), so nothing per pixel hard-wires double. Scene set-up (parsing,
// building transforms) is done in double with GLM and converted once.
#include <glm/glm.hpp>

namespace lattice {

template <typename T>
using Vec3 = glm::vec<3, T, glm::defaultp>;
template <typename T>
using Mat3 = glm::mat<3, 3, T, glm::defaultp>;
template <typename T>
using Mat4 = glm::mat<4, 4, T, glm::defaultp>;

using Vec3d = Vec3<double>;
using Mat4d = Mat4<double>;

// Points and directions through an affine 4x4 matrix (no projective divide).
template <typename T>
inline Vec3<T> transformPoint(const Mat4<T>& m, const Vec3<T>& p) {
  return Vec3<T>(m * glm::vec<4, T, glm::defaultp>(p, T(1)));
}
template <typename T>
inline Vec3<T> transformDirection(const Mat4<T>& m, const Vec3<T>& d) {
  return Vec3<T>(m * glm::vec<4, T, glm::defaultp>(d, T(0)));
}

}  // namespace lattice
