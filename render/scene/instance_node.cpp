#include "render/scene/instance_node.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <limits>
#include <optional>
#include <string>

#include "render/scene/scene.hpp"
#include "foundation/error.hpp"
#include "foundation/transform_condition.hpp"

namespace lattice {
namespace {

// The affine part of a 4x4 map, kept as its three rows: 12 numbers, no w row.
template <typename T>
struct Affine3x4 {
  Vec3<T> row[3];
  T offset[3];

  explicit Affine3x4(const Mat4d& m) {
    for (int r = 0; r < 3; ++r) {
      row[r] = Vec3<T>(static_cast<T>(m[0][r]), static_cast<T>(m[1][r]), static_cast<T>(m[2][r]));
      offset[r] = static_cast<T>(m[3][r]);
    }
  }
  Vec3<T> direction(const Vec3<T>& d) const {
    return Vec3<T>(glm::dot(row[0], d), glm::dot(row[1], d), glm::dot(row[2], d));
  }
  Vec3<T> point(const Vec3<T>& p) const {
    const Vec3<T> v = direction(p);
    return Vec3<T>(v.x + offset[0], v.y + offset[1], v.z + offset[2]);
  }
};

// The box in T, grown by four ulps of its largest coordinate (what rounding
// the box and the ray map to T can move a surface by).
template <typename T>
Bounds<T> paddedIn(const Bounds<double>& world) {
  if (!world.isFinite()) return Bounds<T>::infinite();
  double magnitude = 0.0;
  for (int a = 0; a < 3; ++a) magnitude = std::max({magnitude, std::abs(world.lo[a]), std::abs(world.hi[a])});
  const Vec3d grow(4.0 * double(std::numeric_limits<T>::epsilon()) * magnitude);
  return {Vec3<T>(world.lo - grow), Vec3<T>(world.hi + grow)};
}

template <typename T>
class InstanceNode final : public Primitive<T> {
 public:
  InstanceNode(SharedPrimitive<T> object, const Mat4d& objectToWorld, const Bounds<double>& worldBox)
      : object_(std::move(object)),
        toObject_(glm::inverse(objectToWorld)),
        normalToWorld_(Mat3<T>(glm::inverseTranspose(glm::dmat3(objectToWorld)))),
        bounds_(paddedIn<T>(worldBox)) {}

  const Bounds<T>& bounds() const override { return bounds_; }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    object_->spans(toObject(ray), tmin, tmax, out);
    for (Span<T>& s : out) {
      toWorld(s.enter);
      toWorld(s.leave);
    }
  }

  bool firstHit(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit) const override {
    if (!object_->firstHit(toObject(ray), tmin, tmax, hit)) return false;
    toWorld(hit);
    return true;
  }

  bool firstEnter(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit, bool& inside) const override {
    if (!object_->firstEnter(toObject(ray), tmin, tmax, hit, inside)) return false;
    toWorld(hit);
    return true;
  }

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    return object_->anyHit(toObject(ray), tmin, tmax);
  }

 private:
  Ray<T> toObject(const Ray<T>& ray) const { return {toObject_.point(ray.origin), toObject_.direction(ray.direction)}; }
  // A crossing at infinity (an unbounded solid) has no surface, so no normal to map.
  void toWorld(Hit<T>& hit) const {
    if (std::isfinite(hit.t)) hit.normal = glm::normalize(normalToWorld_ * hit.normal);
  }

  SharedPrimitive<T> object_;
  Affine3x4<T> toObject_;
  Mat3<T> normalToWorld_;
  Bounds<T> bounds_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeInstance(SharedPrimitive<T> object, const Mat4d& objectToWorld, const Bounds<double>& worldBox) {
  checkLeafTransform<T>(objectToWorld, "instance");
  return std::make_unique<InstanceNode<T>>(std::move(object), objectToWorld, worldBox);
}

template PrimitivePtr<float> makeInstance<float>(SharedPrimitive<float>, const Mat4d&, const Bounds<double>&);
template PrimitivePtr<double> makeInstance<double>(SharedPrimitive<double>, const Mat4d&, const Bounds<double>&);

namespace {

// Balls of `radius` at `points`, placed: a ball maps to an ellipsoid whose
// extent along world axis i is radius * |row i of the linear part|, and a
// swept ball lies in the hull of its end balls, so the box of the placed
// balls holds a polyline or a capsule (the box its world-space copy had).
Bounds<double> ballsBounds(const std::vector<Vec3d>& points, double radius, const Mat4d& toWorld) {
  Vec3d half;
  for (int i = 0; i < 3; ++i) half[i] = radius * glm::length(Vec3d(toWorld[0][i], toWorld[1][i], toWorld[2][i]));
  Bounds<double> box;
  for (const Vec3d& p : points) {
    const Vec3d centre = transformPoint(toWorld, p);
    box.extend(centre - half);
    box.extend(centre + half);
  }
  return box;
}

}  // namespace

Bounds<double> placedBounds(const NodeDesc& object, const Mat4d& objectToWorld) {
  const Mat4d toWorld = objectToWorld * object.transform;
  if (object.kind == NodeDesc::Kind::Leaf) {
    const std::optional<LeafShape> shape = object.leaf->shape();
    if (const std::optional<BallChain> balls = shape ? ballsOf(*shape) : std::nullopt)
      return ballsBounds(balls->centres, balls->radius, toWorld);
    return transformBounds(object.leaf->objectBounds(), toWorld);
  }
  const std::size_t operands = object.kind == NodeDesc::Kind::Difference ? 1 : object.children.size();
  Bounds<double> box;
  for (std::size_t i = 0; i < operands && i < object.children.size(); ++i) {
    const Bounds<double> child = placedBounds(object.children[i], toWorld);
    if (!child.empty()) box.extend(child);
  }
  return box;
}

}  // namespace lattice
