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
              LookupStats* stats, LatticeLookup lookup)
      : lht_(std::move(lht)),
        reader_(checked(LhtLookup(*lht_), latticeToWorld), latticeToWorld),
        material_(material),
        castsShadows_(castsShadows),
        stats_(stats),
        lookup_(lookup) {
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
    Span<T> span;
    T enterS, leaveS(0);
    bool haveLeave = false;
    if (lookup_ == LatticeLookup::Blend) {
      if (!blend(local.at(t0), local.at(t1), enterS, span.enter.normal, leaveS, span.leave.normal)) return;
      haveLeave = true;
    } else {
      const LatticePoint in = nearestPoint(local.at(t0));
      const LatticePoint outPoint = nearestPoint(local.at(t1));
      if (in == outPoint) return;
      if (!read(in, outPoint, enterS, span.enter.normal)) return;
      haveLeave = read(outPoint, in, leaveS, span.leave.normal);
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
  // One table read, counted when statistics are on.
  bool read(const LatticePoint& from, const LatticePoint& to, T& s, Vec3<T>& normal) const {
    const bool hit = reader_.read(from, to, s, normal);
    if (stats_) stats_->record(from, to, hit);
    return hit;
  }

  // The lattice points around a chord end on a box face, with bilinear
  // weights: the axis the end is nearest to a grid plane on is the face's
  // and is rounded; the other two keep their fraction. Zero weights are
  // dropped, so an end exactly on a lattice point is one corner.
  struct Corners {
    LatticePoint point[4];
    T weight[4];
    int count = 0;
  };
  Corners cornersOf(const Vec3<T>& p) const {
    const auto& c = lht_->box.cells();
    T v[3], frac[3];
    int base[3];
    int face = 0;
    T nearest = T(1);
    for (int a = 0; a < 3; ++a) {
      v[a] = std::clamp(p[a], T(0), T(c[a]));
      base[a] = static_cast<int>(v[a]);  // floor: v >= 0
      if (base[a] >= c[a]) base[a] = c[a];
      frac[a] = v[a] - T(base[a]);
      const T offGrid = std::min(frac[a], T(1) - frac[a]);
      if (offGrid < nearest) nearest = offGrid, face = a;
    }
    base[face] = static_cast<int>(roundNearest(v[face]));
    frac[face] = T(0);
    const int a = (face + 1) % 3, b = (face + 2) % 3;
    Corners out;
    for (int da = 0; da < 2; ++da)
      for (int db = 0; db < 2; ++db) {
        const T w = (da ? frac[a] : T(1) - frac[a]) * (db ? frac[b] : T(1) - frac[b]);
        if (!(w > T(0))) continue;
        int q[3] = {base[0], base[1], base[2]};
        q[a] += da;
        q[b] += db;
        out.point[out.count] = {static_cast<std::uint8_t>(q[0]), static_cast<std::uint8_t>(q[1]),
                                static_cast<std::uint8_t>(q[2])};
        out.weight[out.count++] = w;
      }
    return out;
  }

  // The blended look-up (lht/lattice_lookup.hpp): false when the hitting
  // pairs hold less than half the weight.
  bool blend(const Vec3<T>& enter, const Vec3<T>& leave, T& enterS, Vec3<T>& enterNormal, T& leaveS,
             Vec3<T>& leaveNormal) const {
    const Corners in = cornersOf(enter), outs = cornersOf(leave);
    struct Pair {
      int i, o;  // corners of the entry and of the exit
      T w;
    };
    // The pairs, heaviest first, so that a ray the object is not near is
    // decided as soon as the missing pairs hold over half the weight.
    Pair pairs[16];
    int pairCount = 0;
    T total(0);
    for (int i = 0; i < in.count; ++i)
      for (int o = 0; o < outs.count; ++o) {
        if (in.point[i] == outs.point[o]) continue;  // no segment
        const Pair pair{i, o, in.weight[i] * outs.weight[o]};
        total += pair.w;
        int k = pairCount++;
        for (; k > 0 && pairs[k - 1].w < pair.w; --k) pairs[k] = pairs[k - 1];
        pairs[k] = pair;
      }
    Pair heaviest{0, 0, T(0)};
    int hitCount = 0;
    T missed(0), covered(0), sSum(0);
    Vec3<T> nSum(T(0)), bestNormal(T(0));
    for (int k = 0; k < pairCount; ++k) {
      const Pair& pair = pairs[k];
      T s;
      Vec3<T> n;
      if (!read(in.point[pair.i], outs.point[pair.o], s, n)) {
        missed += pair.w;
        if (missed + missed > total) return false;
        continue;
      }
      if (hitCount++ == 0) bestNormal = n, heaviest = pair;
      covered += pair.w;
      sSum += pair.w * s;
      nSum += pair.w * n;
    }
    if (hitCount == 0 || covered + covered < total) return false;
    enterS = sSum / covered;
    // Opposite normals can cancel; the heaviest hit's normal stands in.
    enterNormal = lattice::length(nSum) > covered * T(0.25) ? lattice::normalize(nSum) : bestNormal;
    // The exit from the heaviest hitting pair alone: blending it too cost
    // 0.035 s of 0.50 on Plate 6 at f_lat 1 for 0.01 dB (docs/lattices.md).
    if (!read(outs.point[heaviest.o], in.point[heaviest.i], leaveS, leaveNormal)) {
      leaveS = T(0);
      leaveNormal = -enterNormal;
    }
    return true;
  }

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
  LatticeLookup lookup_;
  Mat4<T> worldToLattice_{T(1)};
  Bounds<T> box_;
  Bounds<T> bounds_;
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeLatticeLeaf(std::shared_ptr<const LhtFile> table, const Mat4d& objectToWorld, MaterialId material,
                                bool castsShadows, LookupStats* stats, LatticeLookup lookup) {
  if (!table) throw Error(ErrorKind::Internal, "makeLatticeLeaf: no table");
  const Mat4d latticeToWorld = objectToWorld * table->box.latticeToObject();
  return std::make_unique<LatticeLeaf<T>>(std::move(table), latticeToWorld, material, castsShadows, stats,
                                          lookup);
}

#define LATTICE_INSTANTIATE(T) \
  template PrimitivePtr<T> makeLatticeLeaf<T>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId, bool, LookupStats*, \
                                   LatticeLookup);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice::lht
