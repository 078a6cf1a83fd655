#include "render/shapes/plane_leaf.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <limits>

#include "foundation/error.hpp"

namespace lattice {
namespace {

template <typename T>
class PlaneLeaf final : public Primitive<T> {
 public:
  PlaneLeaf(const QuarticPolynomial& f, const Mat4d& objectToWorld, const Bounds<T>& bounds, MaterialId material)
      : bounds_(bounds), material_(material) {
    const Vec3d a(f.a[std::size_t(QuarticPolynomial::index(1, 0, 0))], f.a[std::size_t(QuarticPolynomial::index(0, 1, 0))],
                  f.a[std::size_t(QuarticPolynomial::index(0, 0, 1))]);
    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(objectToWorld));
    const Vec3d n = normalMatrix * a;
    const double scale = 1.0 / glm::length(n);
    plane_ = Vec3<T>(n * scale);
    constant_ = T((f.a[0] - glm::dot(n, Vec3d(objectToWorld[3]))) * scale);
    // The quartic leaf's normal: its gradient (the linear coefficients, in
    // T) through its normal matrix (in T), divided by its length.
    const Vec3<T> g = Mat3<T>(normalMatrix) * Vec3<T>(a);
    normal_ = g / lattice::length(g);
  }

  const Bounds<T>& bounds() const override { return bounds_; }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    Span<T> span;
    if (crossing(ray, tmin, tmax, span)) out.push_back(span);
  }

  bool firstHit(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit) const override {
    Span<T> span;
    if (!crossing(ray, tmin, tmax, span)) return false;
    // One end is infinite, so at most one end lies strictly inside (tmin, tmax).
    for (const Hit<T>* end : {&span.enter, &span.leave})
      if (end->t > tmin && end->t < tmax) {
        hit = *end;
        return true;
      }
    return false;
  }

  bool firstEnter(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit, bool& inside) const override {
    Span<T> span;
    if (!crossing(ray, tmin, tmax, span)) return false;
    if (span.enter.t <= tmin) {
      inside = true;
      return false;
    }
    hit = span.enter;
    return true;  // crossing() keeps only spans with enter < tmax
  }

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    Hit<T> hit;
    return firstHit(ray, tmin, tmax, hit);
  }

 private:
  // The span the quartic leaf would emit for this ray, if any.
  bool crossing(const Ray<T>& ray, T tmin, T tmax, Span<T>& span) const {
    T c0, c1;
    if (!bounds_.clip(ray, tmin, tmax, c0, c1)) return false;  // as the quartic leaf: its box, its early out
    const T inf = std::numeric_limits<T>::infinity();
    const T atOrigin = lattice::dot(plane_, ray.origin) + constant_;
    const T along = lattice::dot(plane_, ray.direction);
    const Hit<T> below{-inf, Vec3<T>(0), material_}, above{inf, Vec3<T>(0), material_};
    if (along == T(0)) {  // parallel: all inside or all outside (in the plane: no volume)
      if (!(atOrigin < T(0))) return false;
      span = {below, above};
      return true;
    }
    const Hit<T> plane{-atOrigin / along, normal_, material_};
    if (!(plane.t == plane.t)) return false;  // NaN from an infinite origin
    span = along > T(0) ? Span<T>{below, plane} : Span<T>{plane, above};
    return span.leave.t > tmin && span.enter.t < tmax;
  }

  Vec3<T> plane_;  // unit world normal N of f(w) = N . w + constant_
  T constant_;
  Vec3<T> normal_;  // the hit normal, as the quartic leaf computes it
  Bounds<T> bounds_;
  MaterialId material_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makePlaneLeaf(const QuarticPolynomial& f, const Bounds<double>& objectBounds, const Mat4d& objectToWorld,
                              MaterialId material) {
  if (f.degree() != 1) throw Error(ErrorKind::Internal, "makePlaneLeaf: the polynomial is not of degree 1");
  // The quartic leaf of the same shape, built once: its refusals (non-finite
  // or ill-conditioned transforms, coefficients T cannot hold) apply alike,
  // and its world box is the plane's.
  const PrimitivePtr<T> quartic = makeQuarticLeaf<T>(f, objectBounds, objectToWorld, material);
  return std::make_unique<PlaneLeaf<T>>(f, objectToWorld, quartic->bounds(), material);
}

template PrimitivePtr<float> makePlaneLeaf<float>(const QuarticPolynomial&, const Bounds<double>&, const Mat4d&,
                                                  MaterialId);
template PrimitivePtr<double> makePlaneLeaf<double>(const QuarticPolynomial&, const Bounds<double>&, const Mat4d&,
                                                    MaterialId);

}  // namespace lattice
