#pragma once
// The leaves of a union's BVH tested against their items' own oriented boxes,
// four items at once, before any item is called: on the hair plates four
// visits in five reach a lattice whose box the ray's line misses
// (docs/benchmarks.md), and each such visit was a virtual call and a scalar
// clip of its own.
//
// Method:
// * An item that offers an OrientedBox (a lattice leaf: its world -> lattice
//   map and its cells) is culled when its own clip would reject the ray: the
//   same operations in the same order as lht/grid/lattice_chord.hpp's
//   LatticeAffine::apply and clipToCells and the leaf's chord test
//   (t1 > t0, overlapping (tmin, tmax)), so the culled items are exactly the
//   ones that would have answered nothing. An item without a box is kept.
// * Lanes: four items a pass. Double: one 256-bit AVX2 pass, compiled with
//   target("avx2") and chosen at run time (__builtin_cpu_supports), so the
//   binary runs on any x86-64; "fma" is not enabled, so no multiply and add
//   are fused and every lane rounds as the scalar leaf does. Float: one SSE2
//   pass (every x86-64 has SSE2). Eight float lanes would need eight items a
//   leaf, and a BVH leaf holds four or fewer.
// * Where there are no lanes (double on an x86-64 without AVX2, the
//   Cortex-M3, ARM hosts, fixed point) nothing is culled and every item is
//   visited as before: the same answers. The scalar reference cull
//   (CullPath::Portable) does the lane arithmetic one item at a time; tests
//   force it and compare.
// * The lanes also hand over what they computed for each kept item: its ray
//   in the box's coordinates and the chord [t0, t1] (LaneChords), the very
//   numbers the leaf's own clip would compute, so a leaf given them
//   (Primitive::firstEnterClipped) skips its map and clip and answers the same.
// * A cull may keep an item the leaf then rejects (the limit of a
//   front-to-back walk shrinks while a leaf's items are visited; the cull
//   used the larger one), never the other way: which hit wins is unchanged.
#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

#include "foundation/ray.hpp"
#include "foundation/vec.hpp"

namespace lattice {

// A box in an item's own coordinates: world -> box as three columns and a
// translation, applied as (c0 x + c1 y) + (c2 z + c3) to a point and
// (c0 x + c1 y) + c2 z to a direction; the box is [0, extent].
template <typename T>
struct OrientedBox {
  Vec3<T> column[4];
  Vec3<T> extent;
};

// An item's ray in its box's coordinates and the part [t0, t1] of its whole
// line inside the box (t1 > t0), as the item's own clip would make them.
template <typename T>
struct LocalChord {
  Ray<T> local;
  T t0, t1;
};

// The chords of one cull pass, lane k for the item at position first + k;
// bit k of `written` set where lane k's were stored (a kept item with a box).
template <typename T>
struct LaneChords {
  T origin[3][4], direction[3][4], t0[4], t1[4];
  unsigned written = 0;
  LocalChord<T> at(unsigned k) const {
    return {{{origin[0][k], origin[1][k], origin[2][k]}, {direction[0][k], direction[1][k], direction[2][k]}},
            t0[k],
            t1[k]};
  }
};

// Which cull the walks use: Auto (Lanes on x86-64, else None), Lanes (four
// items a pass; uncut for double where the CPU has no AVX2), Portable (the
// scalar reference, for tests), None (every item visited, as before the cull).
enum class CullPath { Auto, Lanes, Portable, None };
// For tests and benchmarks; the default is Auto.
void setCullPath(CullPath path);
// The path in use: Lanes, Portable or None.
CullPath activeCullPath();
// Whether the lanes run for double on this CPU (AVX2).
bool doubleLanesRun();

template <typename T>
class OrientedCull {
 public:
  OrientedCull() = default;
  // boxAt(p, box): fills the box of the item at position p of the BVH's item
  // order and says whether it has one. Each box goes straight into the rows,
  // so no second copy of them is held while the cull is made.
  using BoxAt = std::function<bool(std::uint32_t position, OrientedBox<T>& box)>;
  OrientedCull(std::uint32_t positions, const BoxAt& boxAt);
  // boxes[p], has[p]: the same from lists (tests).
  OrientedCull(const std::vector<OrientedBox<T>>& boxes, const std::vector<bool>& has);

  bool empty() const { return positions_ == 0; }
  // Bit k set (k < count <= 4) when the item at position first + k may answer
  // a query over (tmin, tmax), by the path in use when the cull was made.
  // With `chords`, the kept items' chords are stored there too (its
  // `written` says which; none on the path None).
  unsigned keep(std::uint32_t first, std::uint32_t count, const Ray<T>& ray, T tmin, T tmax,
                LaneChords<T>* chords = nullptr) const {
    if (chords) chords->written = 0;
    if (path_ == CullPath::Lanes) return keepLanes(first, count, ray, tmin, tmax, chords);
    if (path_ == CullPath::Portable) return keepEach(first, count, ray, tmin, tmax, chords);
    return (1u << count) - 1u;
  }
  // The scalar reference of one position (every path agrees with it); with
  // `chord`, a kept item's chord is stored there.
  bool keepOne(std::uint32_t position, const Ray<T>& ray, T tmin, T tmax, LocalChord<T>* chord = nullptr) const;

  // Structure of arrays, one row per quantity, padded by 4 positions so a
  // lane group may read past the last item: rows 0-11 the columns (c0.xyz,
  // c1.xyz, c2.xyz, c3.xyz), 12-14 the extent.
  static constexpr int kRows = 15;

 private:
  const T* row(int r) const { return data_.data() + std::size_t(r) * stride_; }
  unsigned keepLanes(std::uint32_t first, std::uint32_t count, const Ray<T>& ray, T tmin, T tmax,
                     LaneChords<T>* chords) const;
  unsigned keepEach(std::uint32_t first, std::uint32_t count, const Ray<T>& ray, T tmin, T tmax,
                    LaneChords<T>* chords) const;

  std::uint32_t positions_ = 0;
  std::size_t stride_ = 0;
  std::vector<T> data_;
  std::vector<std::uint8_t> has_;  // 1 where the position has a box
  CullPath path_ = CullPath::None;  // resolved when made: Lanes, Portable or None
};

extern template class OrientedCull<float>;
extern template class OrientedCull<double>;

}  // namespace lattice
