// The polyline shape's build (render/shapes/polyline_shape.hpp): one capsule
// per segment, each placed by the rigid map taking the z axis onto it, joined
// by a CSG union.
#include "render/shapes/polyline_shape.hpp"
#include "render/shapes/polyline_parts.hpp"

#include <fmt/format.h>

#include <cmath>

#include "foundation/error.hpp"
#include "render/shapes/composite_shapes.hpp"
#include "render/shapes/csg.hpp"

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

}  // namespace

template <typename T>
PrimitivePtr<T> makePolylineNamingParts(const std::vector<Vec3d>& points, double radius, const Mat4d& objectToWorld,
                                        MaterialId material, std::vector<const Primitive<T>*>& parts) {
  if (points.size() < 2) throw Error(ErrorKind::Input, "a polyline needs at least two points");
  std::vector<PrimitivePtr<T>> pieces;
  parts.clear();
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double length = glm::length(points[i] - points[i - 1]);
    if (!(length > 0.0) || !std::isfinite(length))
      throw Error(ErrorKind::Input, fmt::format("polyline points {} and {} coincide (or are not finite)", i - 1, i));
    pieces.push_back(makeCapsule<T>(radius, length, objectToWorld * segmentFrame(points[i - 1], points[i]), material));
    parts.push_back(pieces.back().get());  // the union keeps the object where it is
  }
  if (pieces.size() == 1) return std::move(pieces.front());
  return makeCsgNode<T>(CsgOp::Union, std::move(pieces));
}

template <typename T>
PrimitivePtr<T> makePolyline(const std::vector<Vec3d>& points, double radius, const Mat4d& objectToWorld,
                             MaterialId material) {
  std::vector<const Primitive<T>*> parts;
  return makePolylineNamingParts<T>(points, radius, objectToWorld, material, parts);
}

#define LATTICE_INSTANTIATE(T)                                                                                 \
  template PrimitivePtr<T> makePolyline<T>(const std::vector<Vec3d>&, double, const Mat4d&, MaterialId);       \
  template PrimitivePtr<T> makePolylineNamingParts<T>(const std::vector<Vec3d>&, double, const Mat4d&, MaterialId, \
                                                      std::vector<const Primitive<T>*>&);
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

std::string PolylineShape::describe() const { return fmt::format("polyline of {} points", points.size()); }

}  // namespace lattice
