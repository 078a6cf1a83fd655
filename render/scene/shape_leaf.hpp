#pragma once
// The scene leaf of any shape the tracer builds itself (a row of
// render/shapes/leaf_shape.hpp with a build: quartic, capsule, polyline).
//
// Method: one template over the shape's struct, which gives the build for
// every arithmetic, the box, the baked form and the name; so a new shape
// needs no leaf class of its own. `name` is what messages call the leaf
// ("sphere" for the capsule of length 0 a scene's sphere is); empty, the
// shape's own describe().
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "render/scene/scene.hpp"
#include "render/scene/scene_baker.hpp"

namespace lattice {

template <typename Shape>
class ShapeLeaf final : public LeafTemplate<ShapeLeaf<Shape>> {
 public:
  ShapeLeaf(Shape shape, std::string name)
      : shape_(std::move(shape)), name_(name.empty() ? shape_.describe() : std::move(name)) {}

  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId material, const BuildOptions&) const {
    return shape_.template build<T>(toWorld, material);
  }
  Bounds<double> objectBounds() const override { return shape_.objectBounds(); }
  std::string describe() const override { return name_; }
#ifndef LATTICE_NO_BAKER  // the firmware renders a baked scene and never bakes one (render/scene/scene.hpp)
  std::string bake(SceneBaker& baker) const override { return shape_.bake(baker, name_); }
#endif
  std::optional<LeafShape> shape() const override { return LeafShape{shape_}; }

 private:
  Shape shape_;
  std::string name_;
};

template <typename Shape>
LeafDescPtr makeShapeLeaf(Shape shape, std::string name = {}) {
  return std::make_shared<ShapeLeaf<Shape>>(std::move(shape), std::move(name));
}

}  // namespace lattice
