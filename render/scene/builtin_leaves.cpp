#include "render/scene/builtin_leaves.hpp"

#include <fmt/format.h>

#include "render/shapes/composite_shapes.hpp"
#include "render/shapes/plane_leaf.hpp"
#include "render/shapes/quadric_leaf.hpp"
#include "render/scene/scene_baker.hpp"

namespace lattice {
namespace {

class QuarticLeafDesc final : public LeafTemplate<QuarticLeafDesc> {
 public:
  QuarticLeafDesc(QuarticShape shape, std::string name)
      : shape_(std::move(shape)), name_(std::move(name)), degree_(shape_.f.degree()) {}
  // A plane (degree 1: half_space) and a quadric (degree 2: cylinder,
  // ellipsoid, cone, ...) are solved in closed form in float and double
  // (render/shapes/plane_leaf.hpp, render/shapes/quadric_leaf.hpp); fixed point, and
  // degrees 3 and 4, keep the quartic leaf.
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId m, const BuildOptions&) const {
    if constexpr (std::is_floating_point_v<T>) {
      if (degree_ == 1) return makePlaneLeaf<T>(shape_.f, shape_.bounds, toWorld, m);
      if (degree_ == 2) return makeQuadricLeaf<T>(shape_.f, shape_.bounds, toWorld, m);
    }
    return makeQuarticLeaf<T>(shape_.f, shape_.bounds, toWorld, m);
  }
  Bounds<double> objectBounds() const override { return shape_.bounds; }
  std::string describe() const override { return name_; }
  LeafShape shape() const override { return LeafShape::ofQuartic(shape_); }
  std::string bake(SceneBaker& baker) const override {
    baker.include("render/scene/builtin_leaves.hpp");
    std::string terms;
    for (std::size_t i = 0; i < shape_.f.a.size(); ++i) terms += (i ? ", " : "") + baker.number(shape_.f.a[i]);
    return fmt::format("lattice::makeQuarticLeafDesc(lattice::QuarticShape{{lattice::QuarticPolynomial{{{{{}}}}}, "
                       "lattice::Bounds<double>{{{}, {}}}}}, \"{}\")",
                       terms, baker.vec3(shape_.bounds.lo), baker.vec3(shape_.bounds.hi), name_);
  }

 private:
  QuarticShape shape_;
  std::string name_;
  int degree_;
};

// A capsule (and a sphere: a capsule of length 0), built by
// render/shapes/composite_shapes.hpp: closed form in float and double, quartics in fixed
// point.
class CapsuleLeafDesc final : public LeafTemplate<CapsuleLeafDesc> {
 public:
  CapsuleLeafDesc(double radius, double length, std::string name)
      : radius_(radius), length_(length), name_(std::move(name)) {}
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId m, const BuildOptions&) const {
    return makeCapsule<T>(radius_, length_, toWorld, m);
  }
  Bounds<double> objectBounds() const override {
    return {Vec3d(-radius_, -radius_, -radius_), Vec3d(radius_, radius_, length_ + radius_)};
  }
  std::string describe() const override { return name_; }
  LeafShape shape() const override { return LeafShape::ofCapsule(radius_, length_); }
  std::string bake(SceneBaker& baker) const override {
    baker.include("render/scene/builtin_leaves.hpp");
    return fmt::format("lattice::makeCapsuleLeafDesc({}, {}, \"{}\")", baker.number(radius_), baker.number(length_),
                       name_);
  }

 private:
  double radius_, length_;
  std::string name_;
};

}  // namespace

LeafDescPtr makeQuarticLeafDesc(QuarticShape shape, std::string name) {
  return std::make_shared<QuarticLeafDesc>(std::move(shape), std::move(name));
}
LeafDescPtr makeCapsuleLeafDesc(double radius, double length, std::string name) {
  return std::make_shared<CapsuleLeafDesc>(radius, length, std::move(name));
}

}  // namespace lattice
