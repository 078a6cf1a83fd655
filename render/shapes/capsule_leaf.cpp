#include "render/shapes/capsule_leaf.hpp"

#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <limits>
#include <string>

#include "foundation/error.hpp"
#include "foundation/transform_condition.hpp"

namespace lattice {
namespace {

// One convex part's interval along the line, with its normals in object space.
template <typename T>
struct Interval {
  T enter = std::numeric_limits<T>::infinity();
  T leave = -std::numeric_limits<T>::infinity();
  Vec3<T> enterNormal{};
  Vec3<T> leaveNormal{};
  bool empty() const { return !(enter < leave); }
};

template <typename T>
class CapsuleLeaf final : public Primitive<T> {
 public:
  CapsuleLeaf(double radius, double length, const Mat4d& objectToWorld, const Bounds<T>& worldBox, MaterialId material)
      : radius_(static_cast<T>(radius)),
        length_(static_cast<T>(length)),
        worldToObject_(Mat4<T>(glm::inverse(objectToWorld))),
        normalMatrix_(Mat3<T>(glm::inverseTranspose(glm::dmat3(objectToWorld)))),
        bounds_(worldBox),
        material_(material) {}

  const Bounds<T>& bounds() const override { return bounds_; }

  void spans(const Ray<T>& worldRay, T tmin, T tmax, SpanList<T>& out) const override {
    Interval<T> whole;
    if (!crossing(worldRay, tmin, tmax, whole)) return;
    out.push_back({{whole.enter, toWorld(whole.enterNormal), material_}, {whole.leave, toWorld(whole.leaveNormal), material_}});
  }

  // What the default reads from spans(), without the span list or the leave's
  // normal: a union asks its children for this (the rasterizer's hair traces).
  bool firstEnter(const Ray<T>& worldRay, T tmin, T tmax, Hit<T>& hit, bool& inside) const override {
    Interval<T> whole;
    if (!crossing(worldRay, tmin, tmax, whole)) return false;
    if (whole.enter <= tmin) {
      inside = true;
      return false;
    }
    hit = {whole.enter, toWorld(whole.enterNormal), material_};
    return true;
  }

  // The default's answer (firstCrossing of spans()) without the span list or
  // the two normals: every shadow ray that reaches the capsule asks this.
  // crossing() has enter < tmax and leave > tmin, so an end lies in
  // (tmin, tmax) exactly when the enter is past tmin or the leave before tmax.
  bool anyHit(const Ray<T>& worldRay, T tmin, T tmax) const override {
    Interval<T> whole;
    return crossing(worldRay, tmin, tmax, whole) && (whole.enter > tmin || whole.leave < tmax);
  }

 private:
  // The line's one interval through the capsule, if it overlaps (tmin, tmax).
  bool crossing(const Ray<T>& worldRay, T tmin, T tmax, Interval<T>& whole) const {
    T c0, c1;
    if (!bounds_.clip(worldRay, tmin, tmax, c0, c1)) return false;
    const Ray<T> ray = worldRay.transformed(worldToObject_);  // t is kept
    whole = ball(ray, T(0));
    if (length_ > T(0)) {  // else a sphere
      widen(whole, ball(ray, length_));
      widen(whole, body(ray));
    }
    return !(whole.empty() || whole.leave <= tmin || whole.enter >= tmax);
  }

  // The ball of radius r about (0, 0, z).
  Interval<T> ball(const Ray<T>& ray, T z) const {
    Interval<T> part;
    const Vec3<T> o = ray.origin - Vec3<T>(0, 0, z);
    const Vec3<T>& d = ray.direction;
    const T a = glm::dot(d, d);
    if (!(a > T(0))) return part;
    const T nearest = -glm::dot(o, d) / a;
    const Vec3<T> p = o + d * nearest;
    const T h = radius_ * radius_ - glm::dot(p, p);
    if (!(h > T(0))) return part;  // a miss or a tangent line: no volume crossed
    const T half = std::sqrt(h / a);
    part.enter = nearest - half;
    part.leave = nearest + half;
    part.enterNormal = o + d * part.enter;
    part.leaveNormal = o + d * part.leave;
    return part;
  }

  // The infinite cylinder of radius r about the z axis, cut to 0 <= z <= L.
  // Only ends on the curved side count (see the header).
  Interval<T> body(const Ray<T>& ray) const {
    Interval<T> part;
    const Vec3<T>& o = ray.origin;
    const Vec3<T>& d = ray.direction;
    const T a = d.x * d.x + d.y * d.y;
    if (!(a > T(0))) return part;  // along the axis: the balls and the body agree, the balls give the normals
    const T nearest = -(o.x * d.x + o.y * d.y) / a;
    const T px = o.x + d.x * nearest, py = o.y + d.y * nearest;
    const T h = radius_ * radius_ - (px * px + py * py);
    if (!(h > T(0))) return part;
    const T half = std::sqrt(h / a);
    const T enter = nearest - half, leave = nearest + half;
    // The slab 0 <= z <= L along the line.
    T slabEnter = -std::numeric_limits<T>::infinity(), slabLeave = std::numeric_limits<T>::infinity();
    if (d.z != T(0)) {
      const T ta = -o.z / d.z, tb = (length_ - o.z) / d.z;
      slabEnter = std::min(ta, tb);
      slabLeave = std::max(ta, tb);
    } else if (o.z < T(0) || o.z > length_) {
      return part;
    }
    if (enter >= slabEnter && enter < slabLeave) {
      part.enter = enter;
      const Vec3<T> at = o + d * enter;
      part.enterNormal = Vec3<T>(at.x, at.y, T(0));
    }
    if (leave <= slabLeave && leave > slabEnter) {
      part.leave = leave;
      const Vec3<T> at = o + d * leave;
      part.leaveNormal = Vec3<T>(at.x, at.y, T(0));
    }
    return part;
  }

  // The union of two intervals of one convex solid: the earliest enter and the
  // latest leave, each with its own normal. Ties go to what is already there
  // (the balls, asked first).
  static void widen(Interval<T>& whole, const Interval<T>& part) {
    if (part.enter < whole.enter) {
      whole.enter = part.enter;
      whole.enterNormal = part.enterNormal;
    }
    if (part.leave > whole.leave) {
      whole.leave = part.leave;
      whole.leaveNormal = part.leaveNormal;
    }
  }

  Vec3<T> toWorld(const Vec3<T>& objectNormal) const { return glm::normalize(normalMatrix_ * objectNormal); }

  T radius_;
  T length_;
  Mat4<T> worldToObject_;
  Mat3<T> normalMatrix_;
  Bounds<T> bounds_;
  MaterialId material_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeCapsuleLeaf(double radius, double length, const Mat4d& objectToWorld, const Bounds<T>& worldBox,
                                MaterialId material) {
  checkLeafTransform<T>(objectToWorld, "capsule");  // as a quartic leaf refuses
  return std::make_unique<CapsuleLeaf<T>>(radius, length, objectToWorld, worldBox, material);
}

template PrimitivePtr<float> makeCapsuleLeaf<float>(double, double, const Mat4d&, const Bounds<float>&, MaterialId);
template PrimitivePtr<double> makeCapsuleLeaf<double>(double, double, const Mat4d&, const Bounds<double>&, MaterialId);

}  // namespace lattice
