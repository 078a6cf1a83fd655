#pragma once
// The thesis's lighting model, eq. 2.3, evaluated per RGB channel:
//
//   I = k_amb I_amb + sum over visible lights i of
//         I_inc,i / (D_i + K) * [ k_diff (n . l_i) + k_spec (r_i . s)^n_spec ]
//
// n   unit surface normal at the hit, turned to face the observer (surfaces
//     are lit on the side the ray arrives from; a solid seen from inside,
//     e.g. the bore of a sphere with a hole, is lit on its inner face),
// l_i unit vector from the hit TOWARDS light i, D_i the distance to it,
// r_i = 2 (l_i . n) n - l_i, the mirror direction of l_i (thesis, fig. 3),
// s   unit vector from the hit TOWARDS the observer. The thesis's prose says
//     s "points from the observer to the intersection"; with that sign r . s
//     would be -1 exactly at the mirror angle, so we use the opposite sign:
//     the highlight sits where the reflected light ray heads for the eye.
//
// Negative dot products are clamped: a light behind the surface (n . l <= 0)
// contributes nothing, and the specular term is 0 when r . s <= 0. Lights are
// "visible" (the thesis's N_vs) when a shadow ray from the hit point to the
// light meets no surface; the result is clamped to [0, 1] per channel.
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/scene/light.hpp"
#include "render/scene/material.hpp"
#include "render/shapes/primitive.hpp"
#include "foundation/vec.hpp"

namespace lattice {

// Everything eq. 2.3 needs besides the hit, already converted to T.
template <typename T>
struct LightingModel {
  Vec3<T> ambient{T(0.2)};  // I_amb
  T attenuationK = T(1);    // K
  std::vector<PointLight<T>> lights;
  std::vector<Material<T>> materials;  // indexed by MaterialId
};

// How far a secondary ray starts off the surface: a few ulps of the
// coordinates' magnitude, more for float whose roots are rougher, so that a
// surface does not shadow itself through rounding ("shadow acne") in scenes
// of any scale.
//
// Fixed point: roots are found to about 2^-32 absolute in t, but the
// polynomial's coefficients are rounded to 2^-32 as well, which moves a
// surface by up to ~1e-5 of the object's size where it is seen at a grazing
// angle; the offset must exceed that.
//
// sceneScale is the smallest length the offset is measured against (1 for
// scenes of unit size and larger). The renderer passes min(1, the camera's
// viewing distance), so a scene a thousandth of a unit across gets offsets a
// thousandth as large: with a fixed floor of 1, a sphere of radius 1e-3 had
// its shadow rays start half a radius off the surface in float (measured
// 20 dB against the unit scene, 28 dB in fixed point, 38 dB in double at 1e-4).
template <typename T>
T surfaceOffset(const Vec3<T>& point, T sceneScale = T(1)) {
  const T scale = std::max({sceneScale, absolute(point.x), absolute(point.y), absolute(point.z)});
  if constexpr (!kIsIeee<T>)
    return fixedConstant<T::kFractionBits>(1e-4) * scale;
  else if constexpr (sizeof(T) <= 4)
    return T(5e-4) * scale;
  else
    return T(1e-6) * scale;
}

// The shadow ray from `point` (normal facing the side the light is on) to
// the light at lightPosition: it starts at the point lifted along the normal
// (surfaceOffset) and reaches the light at t = 1.
template <typename T>
Ray<T> shadowRay(const Vec3<T>& point, const Vec3<T>& normal, const Vec3<T>& lightPosition, T sceneScale = T(1)) {
  const Vec3<T> origin = point + normal * surfaceOffset(point, sceneScale);
  return {origin, lightPosition - origin};
}

// Is the light at lightPosition hidden from `point` by any surface of
// `scene` (anything on the shadow ray for 0 < t < 1)?
template <typename T>
bool inShadow(const Primitive<T>& scene, const Vec3<T>& point, const Vec3<T>& normal, const Vec3<T>& lightPosition,
              T sceneScale = T(1)) {
  return scene.anyHit(shadowRay(point, normal, lightPosition, sceneScale), T(0), T(1));
}

// Eq. 2.3 at one hit. `normal` is the unit world normal as the primitive
// reported it; `toObserver` points from the hit towards the eye (need not be
// unit). isVisible(lightIndex, facingNormal) says whether light i reaches the
// point (the renderer traces a shadow ray; tests may decide directly).
template <typename T, typename IsVisible>
Vec3<T> shade(const LightingModel<T>& model, const Vec3<T>& point, const Vec3<T>& normal, const Vec3<T>& toObserver,
              MaterialId materialId, IsVisible&& isVisible) {
  const Material<T>& m = model.materials[materialId < model.materials.size() ? materialId : 0];
  const Vec3<T> s = lattice::normalize(toObserver);
  Vec3<T> n = normal;
  if (lattice::dot(n, s) < T(0)) n = -n;

  Vec3<T> intensity = m.ambient * model.ambient;
  for (std::size_t i = 0; i < model.lights.size(); ++i) {
    const PointLight<T>& light = model.lights[i];
    const Vec3<T> toLight = light.position - point;
    const T distance = lattice::length(toLight);
    if (!(distance > T(0))) continue;
    const Vec3<T> l = toLight / distance;
    const T nl = lattice::dot(n, l);
    if (nl <= T(0)) continue;  // the light is behind the surface
    if (!isVisible(i, n)) continue;
    const Vec3<T> r = T(2) * nl * n - l;
    const T rs = lattice::dot(r, s);
    Vec3<T> specular(T(0));
    if (rs > T(0)) {  // a channel with no specular skips its power (0 x a finite power is 0 in every arithmetic)
      T exponent = T(0), powered = T(0);
      bool taken = false;  // channels sharing an exponent (the usual material) share one power: same bits
      for (int c = 0; c < 3; ++c) {
        if (m.specular[c] == T(0)) continue;
        if (!taken || !(m.shininess[c] == exponent)) {
          exponent = m.shininess[c];
          powered = power(rs, exponent);
          taken = true;
        }
        specular[c] = m.specular[c] * powered;
      }
    }
    const T denominator = distance + model.attenuationK;
    if (!(denominator > T(0))) continue;  // K < -D: the fudge factor makes no sense here
    intensity += light.intensity / denominator * (m.diffuse * nl + specular);
  }
  return clamp01(intensity);
}

}  // namespace lattice
