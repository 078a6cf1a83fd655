#pragma once
// What every node of the CSG tree is: quartic leaves, lattice leaves and the
// set operations over them (thesis ch. 3: "the only criterion for primitive
// objects in a CSG system is the ability to build ray-object intersection
// lists for them").
//
// A node reports the spans of the ray's *line* that lie inside its solid.
// Spans are kept whole even where they begin before tmin (a ray that starts
// inside a solid gets a span whose enter.t < tmin), because union,
// intersection and difference need to know what is inside at every t.
#include <cstdint>
#include <limits>
#include <memory>

#include "foundation/bounds.hpp"
#include "foundation/ray.hpp"
#include "render/accel/oriented_cull.hpp"
#include "render/shapes/span_list.hpp"

namespace lattice {

// Materials are referred to by index into the scene's material table.
using MaterialId = std::uint32_t;

template <typename T>
struct Hit {
  T t = std::numeric_limits<T>::infinity();
  Vec3<T> normal{};  // world space, unit, pointing out of the solid the span belongs to
  MaterialId material = 0;
};

// [enter.t, leave.t] is inside the solid. enter.t may be -inf and leave.t +inf
// (unbounded solids: half-spaces, cylinders).
template <typename T>
struct Span {
  Hit<T> enter;
  Hit<T> leave;
};

template <typename T>
using SpanList = SmallVector<Span<T>, 8>;

// The first surface crossing of a span list in (tmin, tmax): an enter, or the
// leave of a span that contains tmin.
template <typename T>
bool firstCrossing(const SpanList<T>& list, T tmin, T tmax, Hit<T>& hit) {
  for (const Span<T>& s : list) {
    if (s.enter.t > tmin && s.enter.t < tmax) {
      hit = s.enter;
      return true;
    }
    if (s.leave.t > tmin && s.leave.t < tmax) {
      hit = s.leave;
      return true;
    }
  }
  return false;
}

template <typename T>
class Primitive {
 public:
  virtual ~Primitive() = default;

  // World-space bounding box (may be infinite). Computed once at build time.
  virtual const Bounds<T>& bounds() const = 0;

  // Appends to `out` the spans of the ray inside this solid that overlap
  // (tmin, tmax), sorted by t and disjoint. `out` is empty on entry.
  virtual void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const = 0;

  // The first surface crossing with tmin < t < tmax (an enter, or the leave
  // of a span that contains tmin). The default derives it from spans().
  virtual bool firstHit(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit) const {
    SpanList<T> list;
    spans(ray, tmin, tmax, list);
    return firstCrossing(list, tmin, tmax, hit);
  }

  // The first enter in (tmin, tmax), for a union looking for its nearest
  // child: true with `hit` the enter, or false with `inside` set when the
  // solid contains the ray at tmin (then the caller needs the exact path).
  // The default reads spans(); a union answers from its children's first
  // enters without building and merging their span lists.
  virtual bool firstEnter(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit, bool& inside) const {
    SpanList<T> list;
    spans(ray, tmin, tmax, list);
    if (list.empty()) return false;
    if (list[0].enter.t <= tmin) {
      inside = true;
      return false;
    }
    if (!(list[0].enter.t < tmax)) return false;
    hit = list[0].enter;
    return true;
  }

  // firstEnter for a ray a union's cull has already mapped into this
  // primitive's oriented box and clipped (t1 > t0): `chord` holds exactly what
  // the primitive's own map and clip would give (render/accel/oriented_cull.hpp),
  // so one that has such a box may skip them. The same answer as firstEnter.
  virtual bool firstEnterClipped(const Ray<T>& ray, const LocalChord<T>& /*chord*/, T tmin, T tmax, Hit<T>& hit,
                                 bool& inside) const {
    return firstEnter(ray, tmin, tmax, hit, inside);
  }

  // anyHit from such a chord: the same answer as anyHit. A primitive with an
  // oriented box answers occluder() as itself (the default's way), so a
  // union may ask this in its place.
  virtual bool anyHitClipped(const Ray<T>& ray, const LocalChord<T>& /*chord*/, T tmin, T tmax) const {
    return anyHit(ray, tmin, tmax);
  }

  // A box in the primitive's own coordinates such that it answers nothing
  // (no span, hit or enter) for a ray whose line, mapped into them, misses
  // the box or crosses it outside (tmin, tmax), by the exact test of
  // render/accel/oriented_cull.hpp; a union's BVH then culls such a child
  // without calling it. False (no such box) unless a leaf says otherwise.
  virtual bool orientedBox(OrientedBox<T>& /*box*/) const { return false; }

  // Shadow rays: is there any crossing in (tmin, tmax)? Subclasses make this
  // cheaper than firstHit where they can (stop at the first crossing found).
  virtual bool anyHit(const Ray<T>& ray, T tmin, T tmax) const {
    Hit<T> hit;
    return firstHit(ray, tmin, tmax, hit);
  }

  // The same question, answered with who blocks: a node whose own anyHit is
  // true for this ray (null where anyHit is false). A union hands down its
  // blocking child's answer, so the renderer can ask that one node first
  // for the next shadow ray (render/scene/occluder_cache.hpp); any node
  // answers itself.
  virtual const Primitive<T>* occluder(const Ray<T>& ray, T tmin, T tmax) const {
    return anyHit(ray, tmin, tmax) ? this : nullptr;
  }
};

template <typename T>
using PrimitivePtr = std::unique_ptr<Primitive<T>>;

}  // namespace lattice
