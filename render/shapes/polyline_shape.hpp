#pragma once
// The polyline shape: spheres at the points joined by cylinders of the same
// radius - the thesis's hook (Figure 2) and hair (Plate 5). One alternative
// of LeafShape (render/shapes/leaf_shape.hpp).
//
// Method: built exactly as a union of capsules, one per segment
// (render/shapes/composite_shapes.hpp), so it is closed form wherever a capsule is.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "foundation/arithmetics.hpp"
#include "render/shapes/ball_chain.hpp"
#include "render/shapes/primitive.hpp"

namespace lattice {

// Throws lattice::Error(Input) for fewer than 2 points, coincident
// neighbours or a bad radius.
template <typename T>
PrimitivePtr<T> makePolyline(const std::vector<Vec3d>& points, double radius, const Mat4d& objectToWorld,
                             MaterialId material);

#define LATTICE_DECLARE(T) \
  extern template PrimitivePtr<T> makePolyline<T>(const std::vector<Vec3d>&, double, const Mat4d&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

// The exact box: every point grown by the radius.
Bounds<double> polylineBounds(const std::vector<Vec3d>& points, double radius);

struct PolylineShape {
  static constexpr std::string_view kName = "polyline";
  static constexpr std::array<std::string_view, 2> kKeys{"points", "radius"};
  static constexpr std::string_view kExample = "points = [[0, 0, 0], [0, 0, 1], [1, 0, 1]]\nradius = 0.1";

  std::vector<Vec3d> points;
  double radius = 0.0;

  template <typename Keys>
  static PolylineShape read(Keys& keys) {
    PolylineShape shape;
    shape.radius = keys.positive("radius");
    if (keys.length("points") < 2)
      keys.failTable("a polyline needs `points = [[x, y, z], [x, y, z], ...]` with at least two points");
    shape.points = keys.vec3List("points", "a polyline point");
    for (std::size_t i = 1; i < shape.points.size(); ++i)
      if (shape.points[i] == shape.points[i - 1])
        keys.failItem("points", i, "this polyline point repeats the one before it");
    return shape;
  }

  Bounds<double> objectBounds() const { return polylineBounds(points, radius); }
  std::optional<BallChain> balls() const { return BallChain{points, radius}; }
  std::string describe() const;

  template <typename T>
  PrimitivePtr<T> build(const Mat4d& toWorld, MaterialId material) const {
    return makePolyline<T>(points, radius, toWorld, material);
  }

  // The C++ a baked scene rebuilds it with (render/scene/scene_baker.hpp).
  template <typename Baker>
  std::string bake(Baker& baker, const std::string&) const {
    baker.include("render/scene/builtin_leaves.hpp");
    std::string list;
    for (const Vec3d& p : points) list += (list.empty() ? "" : ", ") + baker.vec3(p);
    return "lattice::makePolylineLeafDesc({" + list + "}, " + baker.number(radius) + ")";
  }
};

}  // namespace lattice
