#pragma once
// The capsule shape: the segment (0,0,0)-(0,0,length) swept by a ball of
// `radius`; a sphere is the capsule of length 0. One alternative of
// LeafShape (render/shapes/leaf_shape.hpp).
//
// Method: built by render/shapes/composite_shapes.hpp, closed form in float and
// double and quartics in fixed point; it states its space as the balls at its
// two ends, which bound it under any placement.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "render/shapes/ball_chain.hpp"
#include "render/shapes/composite_shapes.hpp"

namespace lattice {

struct CapsuleShape {
  static constexpr std::string_view kName = "capsule";
  static constexpr std::array<std::string_view, 2> kKeys{"radius", "length"};
  static constexpr std::string_view kExample = "radius = 0.5\nlength = 2";

  double radius = 0.0;
  double length = 0.0;

  template <typename Keys>
  static CapsuleShape read(Keys& keys) {
    const double r = keys.positive("radius");
    const double l = keys.number("length").value_or(0.0);
    if (l < 0) keys.fail("length", "'length' of a capsule must be >= 0");
    return {r, l};
  }

  Bounds<double> objectBounds() const {
    return {Vec3d(-radius, -radius, -radius), Vec3d(radius, radius, length + radius)};
  }
  std::optional<BallChain> balls() const { return BallChain{{Vec3d(0.0), Vec3d(0.0, 0.0, length)}, radius}; }
  std::string describe() const { return std::string(kName); }

  template <typename T>
  PrimitivePtr<T> build(const Mat4d& toWorld, MaterialId material) const {
    return makeCapsule<T>(radius, length, toWorld, material);
  }

  // The C++ a baked scene rebuilds it with (render/scene/scene_baker.hpp).
  template <typename Baker>
  std::string bake(Baker& baker, const std::string& name) const {
    baker.include("render/scene/builtin_leaves.hpp");
    return "lattice::makeCapsuleLeafDesc(" + baker.number(radius) + ", " + baker.number(length) + ", \"" + name +
           "\")";
  }
};

}  // namespace lattice
