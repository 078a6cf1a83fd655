#include "lht/lattice_leaf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "foundation/transform_condition.hpp"
#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

// The smallest world size of a lattice cell --arith fixed follows.
constexpr double kSmallestFixedPointCell = 1e-6;

template <typename T>
class LatticeLeaf final : public Primitive<T> {
 public:
  LatticeLeaf(std::shared_ptr<const LhtFile> lht, const Mat4d& objectToWorld, MaterialId material, bool castsShadows)
      : lht_(std::move(lht)), precision_(lht_->table.precision()), material_(material), castsShadows_(castsShadows) {
    const Mat4d latticeToWorld = objectToWorld * lht_->box.latticeToObject();
    const std::string problem = conditionProblemFor<T>(latticeToWorld);
    if (!problem.empty()) throw Error(ErrorKind::Input, "lattice: " + problem);
    if constexpr (!kIsIeee<T>) {
      // A ray's box entry and exit are t = (face - origin) / direction in
      // lattice units, and a direction of 1 / (world size of a cell) leaves
      // 1 / direction few Q31.32 bits; normals, multiplied by entries of
      // 1 / cell, saturate. Measured on a sphere lattice: cells of 2.5e-7
      // world units still meet the lattice's own 1.5-cell bound, cells of
      // 2.5e-8 do not (and their normals are 0.65 off unit length), 2.5e-9
      // give garbage. So cells below 1e-6 are refused (docs/stability.md).
      const double cell = singularValueRange(latticeToWorld).smallest;
      if (!(cell >= kSmallestFixedPointCell))
        throw Error(ErrorKind::Input,
                    fmt::format("lattice: a cell of this lattice is {:.3g} world units across, below the 1e-6 that "
                                "--arith fixed resolves (its resolution is 2^-32 = 2.3e-10); use --arith double, "
                                "or scale the whole scene up",
                                cell));
    }
    const Mat4d worldToLattice = glm::inverse(latticeToWorld);
    worldToLattice_ = Mat4<T>(worldToLattice);
    // Normals go back with the inverse transpose of lattice -> world.
    const Mat3<double> normalToWorld = glm::transpose(Mat3<double>(worldToLattice));
    normalToWorld_ = Mat3<T>(normalToWorld);
    // Fixed point multiplies the entry's integer direction (components up to
    // normalDirectionMax: 127, or 32767 for the wide entry) by this matrix.
    // Scaled by a power of two so the product stays as small as with the
    // thesis's 127 (Q31.32 saturates at 2^31); the length does not matter,
    // the result is normalized, and for the thesis the factor is exactly 1.
    const int bits = static_cast<int>(std::bit_width(static_cast<unsigned>(normalDirectionMax(precision_))));
    const int extraBits = std::max(0, bits - 7);
    directionToWorld_ = Mat3<T>(normalToWorld * std::ldexp(1.0, -extraBits));
    const auto& c = lht_->box.cells();
    box_ = {Vec3<T>(T(0)), Vec3<T>(T(c[0]), T(c[1]), T(c[2]))};
    const Bounds<double> world = transformBounds(Bounds<double>{Vec3d(0.0), Vec3d(c[0], c[1], c[2])}, latticeToWorld);
    bounds_ = {Vec3<T>(world.lo), Vec3<T>(world.hi)};
  }

  const Bounds<T>& bounds() const override { return bounds_; }

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    return castsShadows_ && Primitive<T>::anyHit(ray, tmin, tmax);
  }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    const Ray<T> local = ray.transformed(worldToLattice_);
    T t0, t1;
    // The whole line through the box, not just (tmin, tmax): the lookup needs
    // the box's entry and exit even for a ray starting inside it.
    const T inf = std::numeric_limits<T>::infinity();
    if (!box_.clip(local, -inf, inf, t0, t1) || !(t1 > t0)) return;
    if (t1 <= tmin || t0 >= tmax) return;
    const LatticePoint in = nearestPoint(local.at(t0));
    const LatticePoint outPoint = nearestPoint(local.at(t1));
    if (in == outPoint) return;
    Span<T> span;
    bool haveLeave = false;
    T enterS, leaveS(0);
    if constexpr (kIsIeee<T>) {
      const auto enter = lht_->table.find(in, outPoint);
      if (!enter) return;
      const auto leave = lht_->table.find(outPoint, in);
      enterS = T(enter->s);
      span.enter.normal = toWorld(enter->normal);
      if (leave) {
        haveLeave = true;
        leaveS = T(leave->s);
        span.leave.normal = toWorld(leave->normal);
      }
    } else {
      // Fixed point decodes the entry's integers directly (the same decoder
      // as find() uses, before its conversion to double): s is a fraction
      // of integers and the normal an integer direction, normalized below.
      const std::uint8_t* enter = lht_->table.findEntry(in, outPoint);
      if (!enter) return;
      const std::uint8_t* leave = lht_->table.findEntry(outPoint, in);
      const EntryIntegers enterValues = decodeEntryIntegers(enter, precision_);
      enterS = fraction(enterValues);
      span.enter.normal = directionToWorld(enterValues);
      if (leave) {
        haveLeave = true;
        const EntryIntegers leaveValues = decodeEntryIntegers(leave, precision_);
        leaveS = fraction(leaveValues);
        span.leave.normal = directionToWorld(leaveValues);
      }
    }
    span.enter.t = t0 + (t1 - t0) * enterS;
    span.enter.material = material_;
    // (p_o, p_i) hits whenever (p_i, p_o) does (same segment); guard anyway.
    span.leave.t = haveLeave ? t1 - (t1 - t0) * leaveS : span.enter.t;
    if (!haveLeave) span.leave.normal = -span.enter.normal;
    span.leave.material = material_;
    if (span.leave.t < span.enter.t) span.leave.t = span.enter.t;  // a chord thinner than the quantization
    // One cell along the ray, in t: the reach of the rounding error.
    const T cellT = T(1) / lattice::length(local.direction);
    if (span.leave.t <= tmin + cellT && span.enter.t < tmin + cellT) return;  // the surface the ray starts on
    if (span.leave.t <= tmin || span.enter.t >= tmax) return;
    out.push_back(span);
  }

 private:
  LatticePoint nearestPoint(const Vec3<T>& p) const {
    const auto& c = lht_->box.cells();
    const auto coord = [&](int a) {
      const T v = roundNearest(p[a]);
      return static_cast<std::uint8_t>(std::clamp(static_cast<int>(v), 0, c[a]));
    };
    return {coord(0), coord(1), coord(2)};
  }
  Vec3<T> toWorld(const Vec3d& n) const { return lattice::normalize(normalToWorld_ * Vec3<T>(n)); }
  static T fraction(const EntryIntegers& e) { return T(e.sNumerator) / T(e.sDenominator); }
  Vec3<T> directionToWorld(const EntryIntegers& e) const {
    return lattice::normalize(directionToWorld_ * Vec3<T>(T(e.normal[0]), T(e.normal[1]), T(e.normal[2])));
  }

  std::shared_ptr<const LhtFile> lht_;
  LhtPrecision precision_;
  MaterialId material_;
  bool castsShadows_;
  Mat4<T> worldToLattice_{T(1)};
  Mat3<T> normalToWorld_{T(1)};
  Mat3<T> directionToWorld_{T(1)};  // normalToWorld_ scaled for integer directions (fixed point)
  Bounds<T> box_;
  Bounds<T> bounds_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeLatticeLeaf(std::shared_ptr<const LhtFile> table, const Mat4d& objectToWorld, MaterialId material,
                                bool castsShadows) {
  if (!table) throw Error(ErrorKind::Internal, "makeLatticeLeaf: no table");
  return std::make_unique<LatticeLeaf<T>>(std::move(table), objectToWorld, material, castsShadows);
}

template PrimitivePtr<float> makeLatticeLeaf<float>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId, bool);
template PrimitivePtr<double> makeLatticeLeaf<double>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId, bool);
template PrimitivePtr<Fixed32> makeLatticeLeaf<Fixed32>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId,
                                                        bool);

}  // namespace lattice::lht
