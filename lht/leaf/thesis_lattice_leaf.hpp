#pragma once
// The lattice leaf's shared part and its thesis look-up (lht/leaf/lattice_leaf.hpp
// says what the leaf does), as classes so that both the leaf makeLatticeLeaf
// builds and a baked union of lattice instances (lht/leaf/baked_lattice_union.hpp),
// which makes each leaf on the stack from its constant placement, run this one
// code. Internal to lht/leaf/.
//
// Tunables: none.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "foundation/error.hpp"
#include "foundation/transform_condition.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/grid/lattice_chord.hpp"
#include "lht/leaf/lattice_entry_reader.hpp"
#include "lht/leaf/lattice_entry_reader_fixed.hpp"
#include "lht/leaf/lattice_placement.hpp"
#include "lht/leaf/lookup_stats.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "render/shapes/primitive.hpp"

namespace lattice::lht::detail {

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
      : LatticeLeafBase(std::move(lht), latticeToWorld, glm::inverse(latticeToWorld), material, castsShadows, stats) {}
  // A leaf over a table it does not own (it must outlive the leaf), placed by
  // what placement() of a leaf built as above gave: the same answers.
  LatticeLeafBase(const LatticeBox& box, const LhtLookup& table, const LatticePlacement<T>& p)
      : box_(&box),
        reader_(table, p.normalMap),
        material_(p.material),
        castsShadows_(p.castsShadows),
        stats_(nullptr),
        worldToLattice_(p.worldToLattice),
        cells_(T(box.cells()[0]), T(box.cells()[1]), T(box.cells()[2])),
        bounds_(p.bounds) {}

  const Bounds<T>& bounds() const override { return bounds_; }
  // The box clip() tests: its rejects are the union's cull's (the same
  // operations: render/accel/oriented_cull.hpp).
  bool orientedBox(OrientedBox<T>& box) const override {
    for (int c = 0; c < 4; ++c) box.column[c] = worldToLattice_.column(c);
    box.extent = cells_;
    return true;
  }
  LatticePlacement<T> placement() const {
    return {worldToLattice_, reader_.normalMap(), bounds_, material_, castsShadows_};
  }
  bool countsLookups() const { return stats_ != nullptr; }
  // The table it owns; null for a leaf made from a placement.
  const std::shared_ptr<const LhtFile>& table() const { return lht_; }

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
  // The same from the union cull's chord (already t1 > t0): only the test
  // against (tmin, tmax), which may have shrunk since the cull.
  static bool clipped(const LocalChord<T>& from, T tmin, T tmax, Chord& c) {
    c.local = from.local;
    c.t0 = from.t0;
    c.t1 = from.t1;
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

  const LatticeBox& box() const { return *box_; }

  std::shared_ptr<const LhtFile> lht_;  // null when the table is not owned
  const LatticeBox* box_;
  EntryReader<T> reader_;  // entries -> s and world normals, per arithmetic
  MaterialId material_;
  bool castsShadows_;

 private:
  // The inverse taken once, for the walk's map and the reader's normals.
  LatticeLeafBase(std::shared_ptr<const LhtFile> lht, const Mat4d& latticeToWorld, const Mat4d& worldToLattice,
                  MaterialId material, bool castsShadows, LookupStats* stats)
      : lht_(std::move(lht)),
        box_(&lht_->box),
        reader_(checked(LhtLookup(*lht_), latticeToWorld), latticeToWorld, worldToLattice),
        material_(material),
        castsShadows_(castsShadows),
        stats_(stats),
        worldToLattice_(Mat4<T>(worldToLattice)) {
    const auto& c = lht_->box.cells();
    cells_ = Vec3<T>(T(c[0]), T(c[1]), T(c[2]));
    const Bounds<double> world = transformBounds(Bounds<double>{Vec3d(0.0), Vec3d(c[0], c[1], c[2])}, latticeToWorld);
    bounds_ = {Vec3<T>(world.lo), Vec3<T>(world.hi)};
  }

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
  // Only the floating-point unions cull and hand chords; fixed point (the
  // firmware) keeps no second copy of the look-up.
  bool anyHitClipped(const Ray<T>& ray, const LocalChord<T>& chord, T tmin, T tmax) const override {
    if constexpr (!kIsIeee<T>) return anyHit(ray, tmin, tmax);
    if (!this->castsShadows_) return false;
    Chord c;
    if (!Base::clipped(chord, tmin, tmax, c)) return false;
    return blocks(c, tmin, tmax);
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
    return enterOf(locate(ray, tmin, tmax, at), at, hit, inside);
  }
  bool firstEnterClipped(const Ray<T>& ray, const LocalChord<T>& chord, T tmin, T tmax, Hit<T>& hit,
                         bool& inside) const override {
    if constexpr (!kIsIeee<T>) return firstEnter(ray, tmin, tmax, hit, inside);
    Chord c;
    if (!Base::clipped(chord, tmin, tmax, c)) return false;
    Located at;
    return enterOf(locate(c, tmin, tmax, at), at, hit, inside);
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
    if (!this->clip(ray, tmin, tmax, c)) return Found::None;
    return locate(c, tmin, tmax, at);
  }
  // anyHit's answer from a clipped chord.
  bool blocks(Chord& c, T tmin, T tmax) const {
    Located at;
    const Found found = locate(c, tmin, tmax, at);
    return found == Found::EnterAhead || (found == Found::StartsInside && at.leaveT < tmax);
  }
  // firstEnter's answer from what locate found.
  bool enterOf(Found found, const Located& at, Hit<T>& hit, bool& inside) const {
    switch (found) {
      case Found::None: return false;
      case Found::EnterAhead: hit = {at.enterT, this->reader_.normal(at.enterEntry), this->material_}; return true;
      case Found::StartsInside: inside = true; return false;
    }
    return false;
  }
  // locate from the clipped chord (inlined into the one above, so the
  // fixed-point build runs the code it ran before the chords were handed).
  [[gnu::always_inline]] Found locate(Chord& c, T tmin, T tmax, Located& at) const {
    if (!roundEnds(c)) return Found::None;
    at.enterEntry = this->find(c.in, c.out);
    if (!at.enterEntry) return Found::None;
    at.enterT = c.t0 + (c.t1 - c.t0) * this->reader_.s(at.enterEntry);
    if (at.enterT >= tmax) return Found::None;
    // An enter at least the bound past tmin is at least one cell past it:
    // the same answer without oneCell's square root and division.
    if constexpr (!kIsIeee<T>)
      if (at.enterT > tmin && !(at.enterT < tmin + oneCellBound(c.local))) return Found::EnterAhead;
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

}  // namespace lattice::lht::detail
