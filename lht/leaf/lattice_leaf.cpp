#include "lht/leaf/lattice_leaf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "foundation/transform_condition.hpp"
#include "lht/grid/lattice_chord.hpp"
#include "lht/leaf/thesis_lattice_leaf.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice::lht {

namespace {

using detail::LatticeLeafBase;
using detail::ThesisLatticeLeaf;

// The blended look-up (lht/leaf/lookup_mode.hpp). Only spans() is its own:
// anyHit, firstHit and firstEnter are the defaults derived from it, except
// that a lattice that casts no shadows is never hit by a shadow ray.
template <typename T>
class BlendedLatticeLeaf final : public LatticeLeafBase<T> {
  using Base = LatticeLeafBase<T>;
  using typename Base::Chord;

 public:
  using Base::Base;

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    if (!this->castsShadows_) return false;
    return Primitive<T>::anyHit(ray, tmin, tmax);
  }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    Chord chord;
    if (!this->clip(ray, tmin, tmax, chord)) return;
    Span<T> span;
    T enterS, leaveS(0);
    if (!blend(chord.local.at(chord.t0), chord.local.at(chord.t1), enterS, span.enter.normal, leaveS,
               span.leave.normal))
      return;
    this->emitSpan(chord, tmin, tmax, span, enterS, leaveS, true, out);
  }

 private:
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
    const auto& c = this->box().cells();
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

  // The blended look-up (lht/leaf/lookup_mode.hpp): false when the hitting
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
      if (!this->read(in.point[pair.i], outs.point[pair.o], s, n)) {
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
    // The exit from the heaviest hitting pair alone: blending it too costs
    // time for no visible gain (docs/lattices.md gives the measurement).
    if (!this->read(outs.point[heaviest.o], in.point[heaviest.i], leaveS, leaveNormal)) {
      leaveS = T(0);
      leaveNormal = -enterNormal;
    }
    return true;
  }
};

}  // namespace

template <typename T>
PrimitivePtr<T> makeLatticeLeaf(std::shared_ptr<const LhtFile> table, const Mat4d& objectToWorld, MaterialId material,
                                bool castsShadows, LookupStats* stats, LatticeLookup lookup) {
  if (!table) throw Error(ErrorKind::Internal, "makeLatticeLeaf: no table");
  const Mat4d latticeToWorld = objectToWorld * table->box.latticeToObject();
  if (lookup == LatticeLookup::Blend)
    return std::make_unique<BlendedLatticeLeaf<T>>(std::move(table), latticeToWorld, material, castsShadows, stats);
  return std::make_unique<ThesisLatticeLeaf<T>>(std::move(table), latticeToWorld, material, castsShadows, stats);
}

#define LATTICE_INSTANTIATE(T) \
  template PrimitivePtr<T> makeLatticeLeaf<T>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId, bool, LookupStats*, \
                                   LatticeLookup);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice::lht
