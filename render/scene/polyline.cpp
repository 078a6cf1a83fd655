#include "render/scene/polyline.hpp"

#include <fmt/format.h>

#include <cmath>

#include "render/shapes/csg.hpp"
#include "render/shapes/composite_shapes.hpp"
#include "render/scene/scene_baker.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

namespace {

// The rigid map taking the z axis to the segment from a to b.
Mat4d segmentFrame(const Vec3d& a, const Vec3d& b) {
  const Vec3d w = glm::normalize(b - a);
  const Vec3d helper = std::abs(w.x) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
  const Vec3d u = glm::normalize(glm::cross(helper, w));
  const Vec3d v = glm::cross(w, u);  // u x v = w: a proper rotation
  Mat4d m(1.0);
  m[0] = glm::dvec4(u, 0.0);
  m[1] = glm::dvec4(v, 0.0);
  m[2] = glm::dvec4(w, 0.0);
  m[3] = glm::dvec4(a, 1.0);
  return m;
}

class PolylineLeafDesc final : public LeafTemplate<PolylineLeafDesc> {
 public:
  PolylineLeafDesc(std::vector<Vec3d> points, double radius) : points_(std::move(points)), radius_(radius) {}
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId m, const BuildOptions&) const {
    return makePolyline<T>(points_, radius_, toWorld, m);
  }
  Bounds<double> objectBounds() const override { return polylineBounds(points_, radius_); }
  std::string describe() const override { return fmt::format("polyline of {} points", points_.size()); }
  std::string bake(SceneBaker& baker) const override {
    baker.include("render/scene/polyline.hpp");
    std::string points;
    for (const Vec3d& p : points_) points += (points.empty() ? "" : ", ") + baker.vec3(p);
    return fmt::format("lattice::makePolylineLeafDesc({{{}}}, {})", points, baker.number(radius_));
  }
  LeafShape shape() const override { return LeafShape::ofPolyline(points_, radius_); }

 private:
  std::vector<Vec3d> points_;
  double radius_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makePolyline(const std::vector<Vec3d>& points, double radius, const Mat4d& objectToWorld,
                             MaterialId material) {
  if (points.size() < 2) throw Error(ErrorKind::Input, "a polyline needs at least two points");
  std::vector<PrimitivePtr<T>> pieces;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double length = glm::length(points[i] - points[i - 1]);
    if (!(length > 0.0) || !std::isfinite(length))
      throw Error(ErrorKind::Input, fmt::format("polyline points {} and {} coincide (or are not finite)", i - 1, i));
    pieces.push_back(makeCapsule<T>(radius, length, objectToWorld * segmentFrame(points[i - 1], points[i]), material));
  }
  if (pieces.size() == 1) return std::move(pieces.front());
  return makeCsgNode<T>(CsgOp::Union, std::move(pieces));
}

#define LATTICE_INSTANTIATE(T) \
  template PrimitivePtr<T> makePolyline<T>(const std::vector<Vec3d>&, double, const Mat4d&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

Bounds<double> polylineBounds(const std::vector<Vec3d>& points, double radius) {
  Bounds<double> box;
  for (const Vec3d& p : points) {
    box.extend(p - Vec3d(radius));
    box.extend(p + Vec3d(radius));
  }
  return box;
}

LeafDescPtr makePolylineLeafDesc(std::vector<Vec3d> points, double radius) {
  return std::make_shared<PolylineLeafDesc>(std::move(points), radius);
}

}  // namespace lattice
