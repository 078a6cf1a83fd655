#pragma once
// The queries of a union over a BVH (render/shapes/csg.hpp), written once for
// every union that keeps its children its own way: the CSG tree's UnionNode
// (children built in RAM) and a baked scene's union of lattice instances
// (constant data in flash, lht/leaf/baked_lattice_union.hpp). Both answer
// every ray the same way because this is the one copy of the walk.
//
// Method: CRTP. Derived provides
//   bool outsideBox(const Ray<T>&, T tmin, T tmax) const;   // the union's own box test
//   std::size_t unboundedCount() const;                     // children every ray visits
//   template <typename F> decltype(auto) withUnbounded(std::size_t k, F f) const;  // f(const Primitive<T>&)
//   const UnionBvh<T>& bvh() const;                        // the finite children
//   template <typename F> decltype(auto) withItem(std::uint32_t item, F f) const;  // f(const Primitive<T>&)
// and, optionally, const OrientedCull<T>* cull() const: the items' oriented
// boxes in the BVH's item order (render/accel/oriented_cull.hpp), or null
// (a kept item with a box is then asked through firstEnterClipped and
// anyHitClipped with the chord the cull made, so it need not clip again);
// and bool childrenAnswerAlone() const: true where a child's anyHit alone
// makes the union's true (children that outlive the walk, and no cut box
// that could stop a ray a child would block), so occluder() may name the
// child; without it the union names itself.
// and Base is the class UnionCore derives from (Primitive<T>, or a CSG node
// base holding the children).
//
// While no child contains the ray at tmin, the union's first crossing is the
// earliest enter of any child, so subtrees starting beyond the best enter so
// far are skipped. A ray that starts inside a child (rare: shadow rays start
// on surfaces, cameras outside) takes the exact path through spans().
//
// Tunables: none.
#include <cstdint>
#include <type_traits>

#include "render/accel/wide_bvh.hpp"
#include "render/shapes/primitive.hpp"
#include "render/shapes/span_ops.hpp"

namespace lattice {

template <typename T, typename Derived, typename Base>
class UnionCore : public Base {
 public:
  using Base::Base;

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    const Derived& self = derived();
    if (self.outsideBox(ray, tmin, tmax)) return;
    SpanList<T> all;
    auto add = [&](const Primitive<T>& child) {
      SpanList<T> list;
      child.spans(ray, tmin, tmax, list);
      for (const Span<T>& s : list) all.push_back(s);
    };
    for (std::size_t k = 0; k < self.unboundedCount(); ++k) self.withUnbounded(k, add);
    walkAll(ray, tmin, tmax, [&](std::uint32_t item, const LocalChord<T>*) {
      self.withItem(item, add);
      return false;
    });
    coalesceSpans(all);
    for (const Span<T>& s : all) out.push_back(s);
  }

  bool firstHit(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit) const override {
    bool inside = false;
    if (firstEnter(ray, tmin, tmax, hit, inside)) return true;
    if (!inside) return false;
    SpanList<T> all;
    spans(ray, tmin, tmax, all);
    return firstCrossing(all, tmin, tmax, hit);
  }

  // The earliest enter of any child, each child asked for its own first enter
  // only up to the best so far (a nested union recurses without span lists).
  // A child that contains the ray at tmin has a box containing the ray's
  // point at tmin, so the front-to-back walk reaches it whatever the limit.
  bool firstEnter(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit, bool& inside) const override {
    const Derived& self = derived();
    if (self.outsideBox(ray, tmin, tmax)) return false;
    T limit = tmax;
    bool found = false;
    Hit<T> child;
    auto visit = [&](const Primitive<T>& c, T& lim, const LocalChord<T>* chord = nullptr) {
      if (inside) return;
      if (kCulls && chord ? c.firstEnterClipped(ray, *chord, tmin, lim, child, inside)
                          : c.firstEnter(ray, tmin, lim, child, inside)) {
        lim = child.t;
        hit = child;
        found = true;
      }
      if (inside) lim = tmin;  // stops the traversal
    };
    for (std::size_t k = 0; k < self.unboundedCount(); ++k)
      self.withUnbounded(k, [&](const Primitive<T>& c) { visit(c, limit); });
    if (inside) return false;
    walkFrontToBack(ray, tmin, limit, [&](std::uint32_t item, T& lim, const LocalChord<T>* chord) {
      self.withItem(item, [&](const Primitive<T>& c) { visit(c, lim, chord); });
    });
    return found && !inside;
  }

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    const Derived& self = derived();
    if (self.outsideBox(ray, tmin, tmax)) return false;
    for (std::size_t k = 0; k < self.unboundedCount(); ++k)
      if (self.withUnbounded(k, [&](const Primitive<T>& c) { return c.anyHit(ray, tmin, tmax); })) return true;
    // In tree order, not nearest first: with a handful of children per shadow
    // ray, sorting them cost as much as it saved (docs/benchmarks.md, Step 4).
    return walkAll(ray, tmin, tmax, [&](std::uint32_t item, const LocalChord<T>* chord) {
      return self.withItem(item, [&](const Primitive<T>& c) {
        return kCulls && chord ? c.anyHitClipped(ray, *chord, tmin, tmax) : c.anyHit(ray, tmin, tmax);
      });
    });
  }

  // anyHit's walk, in the same order, keeping the child that answered.
  const Primitive<T>* occluder(const Ray<T>& ray, T tmin, T tmax) const override {
    const Derived& self = derived();
    if constexpr (!requires(const Derived& d) { d.childrenAnswerAlone(); }) {
      return anyHit(ray, tmin, tmax) ? this : nullptr;
    } else {
      if (!self.childrenAnswerAlone()) return anyHit(ray, tmin, tmax) ? this : nullptr;
      if (self.outsideBox(ray, tmin, tmax)) return nullptr;
      const Primitive<T>* found = nullptr;
      const auto ask = [&](const Primitive<T>& c) {
        found = c.occluder(ray, tmin, tmax);
        return found != nullptr;
      };
      for (std::size_t k = 0; k < self.unboundedCount(); ++k)
        if (self.withUnbounded(k, ask)) return found;
      walkAll(ray, tmin, tmax, [&](std::uint32_t item, const LocalChord<T>* chord) {
        if (!kCulls || !chord) return self.withItem(item, ask);
        return self.withItem(item, [&](const Primitive<T>& c) {  // a leaf with a box answers as itself
          found = c.anyHitClipped(ray, *chord, tmin, tmax) ? &c : nullptr;
          return found != nullptr;
        });
      });
      return found;
    }
  }

 private:
  // The BVH's walks, through the oriented-box cull where Derived keeps one.
  static constexpr bool kCulls = std::is_floating_point_v<T> && requires(const Derived& d) { d.cull(); };
  // visit(item, chord), chord as walkFrontToBack's.
  template <typename Visit>
  bool walkAll(const Ray<T>& ray, T tmin, T tmax, Visit&& visit) const {
    if constexpr (kCulls) {
      if (const OrientedCull<T>* c = derived().cull()) {
        const std::uint32_t* items = derived().bvh().items().data();
        LaneChords<T> lanes;
        std::uint32_t laneFirst = 0;
        return derived().bvh().visitAll(
            ray, tmin, tmax,
            [&](std::uint32_t item) {
              const LocalChord<T>* chord = nullptr;
              LocalChord<T> found;
              if (chordOf(lanes, items + laneFirst, item, found)) chord = &found;
              return visit(item, chord);
            },
            [&](std::uint32_t first, std::uint32_t count, T lo, T hi) {
              laneFirst = first;
              return c->keep(first, count, ray, lo, hi, &lanes);
            });
      }
    }
    // Without chords (fixed point, the firmware, a union with no cull) the
    // BVH's own walk, the visit inlined into it.
    return derived().bvh().visitAll(ray, tmin, tmax,
                                    [&](std::uint32_t item) __attribute__((always_inline)) { return visit(item, nullptr); });
  }
  // The chord the last cull pass (positions from `items`) made for `item`.
  static bool chordOf(const LaneChords<T>& lanes, const std::uint32_t* items, std::uint32_t item, LocalChord<T>& chord) {
    for (unsigned k = 0, w = lanes.written; w != 0; ++k, w >>= 1)
      if ((w & 1u) && items[k] == item) {
        chord = lanes.at(k);
        return true;
      }
    return false;
  }
  // visit(item, limit, chord): chord is the cull's for the item (null when
  // it made none), found by the item's position in the pass just culled.
  template <typename Visit>
  void walkFrontToBack(const Ray<T>& ray, T tmin, T& limit, Visit&& visit) const {
    if constexpr (kCulls) {
      if (const OrientedCull<T>* c = derived().cull()) {
        const std::uint32_t* items = derived().bvh().items().data();
        LaneChords<T> lanes;
        std::uint32_t laneFirst = 0;
        derived().bvh().visitFrontToBack(
            ray, tmin, limit,
            [&](std::uint32_t item, T& lim) {
              LocalChord<T> found;
              visit(item, lim, chordOf(lanes, items + laneFirst, item, found) ? &found : nullptr);
            },
            [&](std::uint32_t first, std::uint32_t count, T lo, T hi) {
              laneFirst = first;
              return c->keep(first, count, ray, lo, hi, &lanes);
            });
        return;
      }
    }
    derived().bvh().visitFrontToBack(ray, tmin, limit,
                                     [&](std::uint32_t item, T& lim) __attribute__((always_inline)) { visit(item, lim, nullptr); });
  }

  const Derived& derived() const { return static_cast<const Derived&>(*this); }
};

}  // namespace lattice
