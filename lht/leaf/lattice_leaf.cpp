#include "lht/leaf/lattice_leaf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "foundation/transform_condition.hpp"
#include "lht/grid/lattice_chord.hpp"
#include "lht/leaf/lattice_entry_reader.hpp"
#include "lht/leaf/lattice_entry_reader_fixed.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice::lht {

namespace {

// What both look-ups share: the lattice's placement and bounds, the chord
// of a ray through the box, one counted table read, and the rules that turn
// an entry's and an exit's s into the span. The look-up itself is the
// subclass's (ThesisLatticeLeaf, BlendedLatticeLeaf), so no query asks
// which look-up it is.
template <typename T>
class LatticeLeafBase : public Primitive<T> {
 public:
  // latticeToWorld: the lattice box's own map, then the instance's transform.
  LatticeLeafBase(std::shared_ptr<const LhtFile> lht, const Mat4d& latticeToWorld, MaterialId material,
                  bool castsShadows, LookupStats* stats)
      : lht_(std::move(lht)),
        reader_(checked(LhtLookup(*lht_), latticeToWorld), latticeToWorld),
        material_(material),
        castsShadows_(castsShadows),
        stats_(stats),
        worldToLattice_(Mat4<T>(glm::inverse(latticeToWorld))) {
    const auto& c = lht_->box.cells();
    cells_ = Vec3<T>(T(c[0]), T(c[1]), T(c[2]));
    const Bounds<double> world = transformBounds(Bounds<double>{Vec3d(0.0), Vec3d(c[0], c[1], c[2])}, latticeToWorld);
    bounds_ = {Vec3<T>(world.lo), Vec3<T>(world.hi)};
  }

  const Bounds<T>& bounds() const override { return bounds_; }

 protected:
  // The ray in lattice coordinates, its chord [t0, t1] through the box, and
  // the grid points nearest the chord's ends.
  struct Chord {
    Ray<T> local;
    T t0, t1;
    LatticePoint in, out;
  };
  // False when the line misses the box or the chord is outside (tmin, tmax).
  // The whole line, not just (tmin, tmax): the look-up needs the box's entry
  // and exit even for a ray starting inside it.
  bool clip(const Ray<T>& ray, T tmin, T tmax, Chord& c) const {
    c.local = worldToLattice_.apply(ray);
    if (!clipToCells(c.local, cells_, c.t0, c.t1) || !(c.t1 > c.t0)) return false;
    return !(c.t1 <= tmin || c.t0 >= tmax);
  }
  // One cell along the ray, in t: the reach of the rounding error.
  static T oneCell(const Chord& c) { return T(1) / lattice::length(c.local.direction); }

  // The span from the entry's s and normal and, when haveLeave, the exit's,
  // appended unless a rule below drops it.
  void emitSpan(const Chord& chord, T tmin, T tmax, Span<T> span, T enterS, T leaveS, bool haveLeave,
                SpanList<T>& out) const {
    const T t0 = chord.t0, t1 = chord.t1;
    span.enter.t = t0 + (t1 - t0) * enterS;
    span.enter.material = material_;
    // (p_o, p_i) hits whenever (p_i, p_o) does (same segment); guard anyway.
    span.leave.t = haveLeave ? t1 - (t1 - t0) * leaveS : span.enter.t;
    if (!haveLeave) span.leave.normal = -span.enter.normal;
    span.leave.material = material_;
    if (span.leave.t < span.enter.t) span.leave.t = span.enter.t;  // a chord thinner than the quantization
    const T cellT = oneCell(chord);
    if (span.leave.t <= tmin + cellT && span.enter.t < tmin + cellT) return;  // the surface the ray starts on
    if (span.leave.t <= tmin || span.enter.t >= tmax) return;
    out.push_back(span);
  }

  // One table look-up, counted when statistics are on.
  const std::uint8_t* find(const LatticePoint& from, const LatticePoint& to) const {
    const std::uint8_t* entry = reader_.find(from, to);
    if (stats_) stats_->record(from, to, entry != nullptr);
    return entry;
  }
  // One table read with s and the normal.
  bool read(const LatticePoint& from, const LatticePoint& to, T& s, Vec3<T>& normal) const {
    const std::uint8_t* entry = find(from, to);
    if (!entry) return false;
    s = reader_.s(entry);
    normal = reader_.normal(entry);
    return true;
  }

  const LatticeBox& box() const { return lht_->box; }

  std::shared_ptr<const LhtFile> lht_;
  EntryReader<T> reader_;  // entries -> s and world normals, per arithmetic
  MaterialId material_;
  bool castsShadows_;

 private:
  // The transform is held to T's condition limit before the reader sees it.
  static LhtLookup checked(LhtLookup table, const Mat4d& latticeToWorld) {
    const std::string problem = conditionProblemFor<T>(latticeToWorld);
    if (!problem.empty()) throw Error(ErrorKind::Input, "lattice: " + problem);
    return table;
  }

  LookupStats* stats_;  // null unless --lht-stats
  LatticeAffine<T> worldToLattice_;
  Vec3<T> cells_;  // the box in lattice coordinates is [0, cells_]
  Bounds<T> bounds_;
};

// The thesis look-up (lht/leaf/lookup_mode.hpp): the chord's ends rounded to
// the nearest lattice points, one pair read each way. The three queries give
// what the defaults derive from spans(), reading the exit only when the entry
// does not settle the answer and decoding a normal only for the crossing
// returned.
template <typename T>
class ThesisLatticeLeaf final : public LatticeLeafBase<T> {
  using Base = LatticeLeafBase<T>;
  using typename Base::Chord;

 public:
  using Base::Base;

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    if (!this->castsShadows_) return false;
    Located at;
    const Found found = locate(ray, tmin, tmax, at);
    return found == Found::EnterAhead || (found == Found::StartsInside && at.leaveT < tmax);
  }

  bool firstHit(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit) const override {
    Located at;
    switch (locate(ray, tmin, tmax, at)) {
      case Found::None: return false;
      case Found::EnterAhead: hit = {at.enterT, this->reader_.normal(at.enterEntry), this->material_}; return true;
      case Found::StartsInside:
        if (!(at.leaveT < tmax)) return false;
        hit = {at.leaveT, at.leaveEntry ? this->reader_.normal(at.leaveEntry) : -this->reader_.normal(at.enterEntry),
               this->material_};
        return true;
    }
    return false;
  }

  bool firstEnter(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit, bool& inside) const override {
    Located at;
    switch (locate(ray, tmin, tmax, at)) {
      case Found::None: return false;
      case Found::EnterAhead: hit = {at.enterT, this->reader_.normal(at.enterEntry), this->material_}; return true;
      case Found::StartsInside: inside = true; return false;
    }
    return false;
  }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    Chord chord;
    if (!this->clip(ray, tmin, tmax, chord) || !roundEnds(chord)) return;
    Span<T> span;
    T enterS, leaveS(0);
    if (!this->read(chord.in, chord.out, enterS, span.enter.normal)) return;
    const bool haveLeave = this->read(chord.out, chord.in, leaveS, span.leave.normal);
    this->emitSpan(chord, tmin, tmax, span, enterS, leaveS, haveLeave, out);
  }

 private:
  // p_i and p_o; false when they coincide (no segment to look up).
  bool roundEnds(Chord& c) const {
    c.in = nearestPoint(c.local.at(c.t0));
    c.out = nearestPoint(c.local.at(c.t1));
    return !(c.in == c.out);
  }
  LatticePoint nearestPoint(const Vec3<T>& p) const {
    const auto& c = this->box().cells();
    return {nearestGridCoordinate(p[0], c[0]), nearestGridCoordinate(p[1], c[1]), nearestGridCoordinate(p[2], c[2])};
  }

  // Where the span spans() would give lies against (tmin, tmax): none (no
  // span, or dropped), its enter inside (tmin, tmax), or it contains tmin.
  enum class Found { None, EnterAhead, StartsInside };
  struct Located {
    const std::uint8_t* enterEntry = nullptr;
    const std::uint8_t* leaveEntry = nullptr;  // null when unread or absent
    T enterT, leaveT;                          // leaveT set for StartsInside
  };
  // spans() drops a span that is the surface the ray starts on (leave and
  // enter within one cell of tmin), ends by tmin, or starts at or after
  // tmax; an enter in (tmin, tmax) at least one cell past tmin survives every
  // rule whatever the exit says, so the exit is then not read.
  Found locate(const Ray<T>& ray, T tmin, T tmax, Located& at) const {
    Chord c;
    if (!this->clip(ray, tmin, tmax, c) || !roundEnds(c)) return Found::None;
    at.enterEntry = this->find(c.in, c.out);
    if (!at.enterEntry) return Found::None;
    at.enterT = c.t0 + (c.t1 - c.t0) * this->reader_.s(at.enterEntry);
    if (at.enterT >= tmax) return Found::None;
    const T past = tmin + Base::oneCell(c);
    if (at.enterT > tmin && !(at.enterT < past)) return Found::EnterAhead;
    at.leaveEntry = this->find(c.out, c.in);
    at.leaveT = at.leaveEntry ? c.t1 - (c.t1 - c.t0) * this->reader_.s(at.leaveEntry) : at.enterT;
    if (at.leaveT < at.enterT) at.leaveT = at.enterT;
    if (at.leaveT <= past && at.enterT < past) return Found::None;
    if (at.leaveT <= tmin) return Found::None;
    return at.enterT > tmin ? Found::EnterAhead : Found::StartsInside;
  }
};

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
    // The exit from the heaviest hitting pair alone: blending it too cost
    // 0.035 s of 0.50 on Plate 6 at f_lat 1 for 0.01 dB (docs/lattices.md).
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
