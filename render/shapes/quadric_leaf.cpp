#include "render/shapes/quadric_leaf.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <cmath>
#include <limits>

#include "foundation/error.hpp"
#include "render/shapes/quartic_arithmetic.hpp"

namespace lattice {
namespace {

template <typename T>
class QuadricLeaf final : public Primitive<T> {
 public:
  QuadricLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds, const Mat4d& objectToWorld,
              const Bounds<T>& bounds, MaterialId material)
      : arithmetic_(glm::inverse(objectToWorld)),
        normalMatrix_(Mat3<T>(glm::inverseTranspose(glm::dmat3(objectToWorld)))),
        linear_(Mat3<T>(glm::dmat3(objectToWorld))),
        bounds_(bounds),
        material_(material) {
    const auto at = [&](int i, int j, int k) { return f.a[std::size_t(QuarticPolynomial::index(i, j, k))]; };
    glm::dmat3 a(0.0);
    a[0][0] = at(2, 0, 0);
    a[1][1] = at(0, 2, 0);
    a[2][2] = at(0, 0, 2);
    a[0][1] = a[1][0] = 0.5 * at(1, 1, 0);
    a[0][2] = a[2][0] = 0.5 * at(1, 0, 1);
    a[1][2] = a[2][1] = 0.5 * at(0, 1, 1);
    quadratic_ = Mat3<T>(a);
    linearTerm_ = Vec3<T>(at(1, 0, 0), at(0, 1, 0), at(0, 0, 1));
    constant_ = T(at(0, 0, 0));
    // The quartic leaf's pivot: the middle of the object box, 0 along unbounded axes.
    for (int ax = 0; ax < 3; ++ax) {
      const double lo = objectBounds.lo[ax], hi = objectBounds.hi[ax];
      pivot_[ax] = std::isfinite(lo) && std::isfinite(hi) ? T(0.5 * (lo + hi)) : T(0);
    }
  }

  const Bounds<T>& bounds() const override { return bounds_; }

  void spans(const Ray<T>& worldRay, T tmin, T tmax, SpanList<T>& out) const override {
    T c0, c1;
    if (!bounds_.clip(worldRay, tmin, tmax, c0, c1)) return;
    ObjectRay<T> ray;
    if (!arithmetic_.toObject(worldRay, pivot_, ray)) return;
    const Vec3<T> inBase = quadratic_ * ray.base, inU = quadratic_ * ray.u;
    // f(base + u s) = a s^2 + b s + c.
    const T a = lattice::dot(ray.u, inU);
    const T b = T(2) * lattice::dot(inBase, ray.u) + lattice::dot(linearTerm_, ray.u);
    const T c = lattice::dot(ray.base, inBase) + lattice::dot(linearTerm_, ray.base) + constant_;
    const T inf = std::numeric_limits<T>::infinity();
    if (a == T(0)) {  // along a ruling or the axis of a paraboloid: degree 1 or 0
      if (b == T(0)) {
        if (c < T(0)) out.push_back({{-inf, Vec3<T>(0), material_}, {inf, Vec3<T>(0), material_}});
        return;
      }
      const T root = -c / b;
      if (b > T(0))
        emit(ray, -inf, root, tmin, tmax, out);
      else
        emit(ray, root, inf, tmin, tmax, out);
      return;
    }
    const T disc = b * b - T(4) * a * c;
    if (!(disc > T(0))) {  // no real root, or a tangent: the sign of a throughout
      if (!(a < T(0))) return;
      if (disc == T(0)) {  // inside on both sides of a touching point: split there, as the quartic leaf does
        const T touch = -b / (T(2) * a);
        emit(ray, -inf, touch, tmin, tmax, out);
        emit(ray, touch, inf, tmin, tmax, out);
      } else {
        emit(ray, -inf, inf, tmin, tmax, out);
      }
      return;
    }
    const T q = T(-0.5) * (b + std::copysign(std::sqrt(disc), b));
    T r0 = q / a, r1 = c / q;
    if (r1 < r0) std::swap(r0, r1);
    if (a > T(0)) {
      emit(ray, r0, r1, tmin, tmax, out);
    } else {
      emit(ray, -inf, r0, tmin, tmax, out);
      emit(ray, r1, inf, tmin, tmax, out);
    }
  }

 private:
  Hit<T> hitAt(const ObjectRay<T>& ray, T s, T facing) const {
    Hit<T> h;
    h.material = material_;
    if (!std::isfinite(s)) {
      h.t = s;
      return h;
    }
    h.t = ray.t0 + arithmetic_.sToT(s, ray.len);
    const Vec3<T> x = ray.base + ray.u * s;
    const Vec3<T> n = normalMatrix_ * (T(2) * (quadratic_ * x) + linearTerm_);
    const T length = lattice::length(n);
    if (length > T(0) && std::isfinite(length)) {
      h.normal = n / length;
    } else {  // a vanishing gradient (a cone's apex) has no normal: face the ray
      const Vec3<T> along = linear_ * ray.u;
      h.normal = along * (facing / lattice::length(along));
    }
    return h;
  }

  // The quartic leaf's filter: a span with volume, overlapping (tmin, tmax).
  void emit(const ObjectRay<T>& ray, T s0, T s1, T tmin, T tmax, SpanList<T>& out) const {
    if (!(s1 > s0)) return;
    const Hit<T> enter = hitAt(ray, s0, T(-1)), leave = hitAt(ray, s1, T(1));
    if (!(leave.t > tmin && enter.t < tmax)) return;
    if (!(leave.t > enter.t)) return;
    out.push_back({enter, leave});
  }

  QuarticArithmetic<T> arithmetic_;  // world -> object for rays, as the quartic leaf
  Mat3<T> normalMatrix_;
  Mat3<T> linear_;  // object -> world for directions
  Mat3<T> quadratic_;
  Vec3<T> linearTerm_;
  T constant_;
  Vec3<T> pivot_{};
  Bounds<T> bounds_;
  MaterialId material_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeQuadricLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds,
                                const Mat4d& objectToWorld, MaterialId material) {
  if (f.degree() != 2) throw Error(ErrorKind::Internal, "makeQuadricLeaf: the polynomial is not of degree 2");
  // The quartic leaf of the same shape, built once: its refusals apply alike,
  // and its world box is the quadric's.
  const PrimitivePtr<T> quartic = makeQuarticLeaf<T>(f, objectBounds, objectToWorld, material);
  return std::make_unique<QuadricLeaf<T>>(f, objectBounds, objectToWorld, quartic->bounds(), material);
}

template PrimitivePtr<float> makeQuadricLeaf<float>(const QuarticPolynomial&, const Bounds<double>&, const Mat4d&,
                                                    MaterialId);
template PrimitivePtr<double> makeQuadricLeaf<double>(const QuarticPolynomial&, const Bounds<double>&, const Mat4d&,
                                                      MaterialId);

}  // namespace lattice
