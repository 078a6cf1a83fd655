#pragma once
// The quartic shape: the solid f(x, y, z) < 0 inside a box known to contain
// it (thesis eq. 3.1). One alternative of LeafShape (render/shapes/leaf_shape.hpp);
// the named presets (render/shapes/quartic_presets.hpp) all return one.
//
// Method: the shape holds only its polynomial and box. It builds the closed
// form its degree allows in float and double (a plane for degree 1, a
// quadric for 2: render/shapes/plane_leaf.hpp, render/shapes/quadric_leaf.hpp)
// and the quartic leaf otherwise, and in fixed point always, because the
// closed forms are written for floating point only.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "foundation/bounds.hpp"
#include "render/shapes/ball_chain.hpp"
#include "render/shapes/plane_leaf.hpp"
#include "render/shapes/quadric_leaf.hpp"
#include "render/shapes/quartic.hpp"

namespace lattice {

struct QuarticShape {
  static constexpr std::string_view kName = "quartic";
  static constexpr std::array<std::string_view, 2> kKeys{"coefficients", "bounds"};
  static constexpr std::string_view kExample = "coefficients = { x2y0z0 = 1, x0y2z0 = 1, x0y0z2 = 1, x0y0z0 = -1 }";

  QuarticPolynomial f;
  Bounds<double> bounds;

  template <typename Keys>
  static QuarticShape read(Keys& keys) {
    QuarticShape shape{keys.polynomial("coefficients"), Bounds<double>::infinite()};
    if (shape.f.degree() < 1)
      keys.fail("coefficients", "a quartic needs at least one non-constant term (f = constant has no surface)");
    if (const auto box = keys.box("bounds")) shape.bounds = *box;
    return shape;
  }

  Bounds<double> objectBounds() const { return bounds; }
  std::optional<BallChain> balls() const { return std::nullopt; }  // only its box is known
  std::string describe() const { return std::string(kName); }

  template <typename T>
  PrimitivePtr<T> build(const Mat4d& toWorld, MaterialId material) const {
    if constexpr (std::is_floating_point_v<T>) {
      const int degree = f.degree();
      if (degree == 1) return makePlaneLeaf<T>(f, bounds, toWorld, material);
      if (degree == 2) return makeQuadricLeaf<T>(f, bounds, toWorld, material);
    }
    return makeQuarticLeaf<T>(f, bounds, toWorld, material);
  }

  // The C++ a baked scene rebuilds it with (render/scene/scene_baker.hpp).
  template <typename Baker>
  std::string bake(Baker& baker, const std::string& name) const {
    baker.include("render/scene/builtin_leaves.hpp");
    std::string terms;
    for (std::size_t i = 0; i < f.a.size(); ++i) terms += (i ? ", " : "") + baker.number(f.a[i]);
    return "lattice::makeQuarticLeafDesc(lattice::QuarticShape{lattice::QuarticPolynomial{{" + terms +
           "}}, lattice::Bounds<double>{" + baker.vec3(bounds.lo) + ", " + baker.vec3(bounds.hi) + "}}, \"" + name +
           "\")";
  }
};

}  // namespace lattice
