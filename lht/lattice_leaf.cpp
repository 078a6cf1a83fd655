#include "lht/lattice_leaf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "foundation/transform_condition.hpp"
#include "lht/lattice_entry_reader.hpp"
#include "lht/lattice_entry_reader_fixed.hpp"
#include "lht/lht_lookup.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice::lht {

namespace {

template <typename T>
class LatticeLeaf final : public Primitive<T> {
 public:
  // latticeToWorld: the lattice box's own map, then the instance's transform.
  LatticeLeaf(std::shared_ptr<const LhtFile> lht, const Mat4d& latticeToWorld, MaterialId material, bool castsShadows,
              LookupStats* stats)
      : lht_(std::move(lht)),
        reader_(checked(LhtLookup(*lht_), latticeToWorld), latticeToWorld),
        material_(material),
        castsShadows_(castsShadows),
        stats_(stats) {
    worldToLattice_ = Mat4<T>(glm::inverse(latticeToWorld));
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
    T enterS, leaveS(0);
    const bool haveEnter = reader_.read(in, outPoint, enterS, span.enter.normal);
    if (stats_) stats_->record(in, outPoint, haveEnter);
    if (!haveEnter) return;
    const bool haveLeave = reader_.read(outPoint, in, leaveS, span.leave.normal);
    if (stats_) stats_->record(outPoint, in, haveLeave);
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
  // The transform is held to T's condition limit before the reader sees it.
  static LhtLookup checked(LhtLookup table, const Mat4d& latticeToWorld) {
    const std::string problem = conditionProblemFor<T>(latticeToWorld);
    if (!problem.empty()) throw Error(ErrorKind::Input, "lattice: " + problem);
    return table;
  }

  std::shared_ptr<const LhtFile> lht_;
  EntryReader<T> reader_;  // entries -> s and world normals, per arithmetic
  MaterialId material_;
  bool castsShadows_;
  LookupStats* stats_;  // null unless --lht-stats
  Mat4<T> worldToLattice_{T(1)};
  Bounds<T> box_;
  Bounds<T> bounds_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeLatticeLeaf(std::shared_ptr<const LhtFile> table, const Mat4d& objectToWorld, MaterialId material,
                                bool castsShadows, LookupStats* stats) {
  if (!table) throw Error(ErrorKind::Internal, "makeLatticeLeaf: no table");
  const Mat4d latticeToWorld = objectToWorld * table->box.latticeToObject();
  return std::make_unique<LatticeLeaf<T>>(std::move(table), latticeToWorld, material, castsShadows, stats);
}

#define LATTICE_INSTANTIATE(T) \
  template PrimitivePtr<T> makeLatticeLeaf<T>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId, bool, LookupStats*);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice::lht
