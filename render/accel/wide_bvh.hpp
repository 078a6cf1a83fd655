#pragma once
// A 4- or 8-wide BVH: the binary SAH tree of render/accel/bvh.hpp collapsed so
// that each node holds up to four (or eight) children's boxes in float, tested
// with one 4-lane SSE slab test (render/accel/wide_slab.hpp) or one 8-lane AVX
// test (render/accel/wide_slab8.hpp) instead of a double test per box. The
// union of a scene's children (render/shapes/csg.cpp) walks it for float and
// double rays; fixed point keeps the binary tree, whose Q31.32 boxes have no
// conservative float form without a range check per box.
//
// Method and tunables:
//  * Collapse: starting from a binary node's two children, the inner child
//    with the largest surface area is replaced by its two children until
//    there are four (eight) or only binary leaves remain (the usual collapse
//    of a binary SAH tree, as Embree's BVH4 and BVH8 builders and Wald et al.,
//    "Getting rid of packets", 2008, describe). Binary leaves (up to 4 items)
//    become leaf lanes; in the 8-wide form, where the caller culls a leaf's
//    items (LeafItems::Culled), a whole binary subtree of at most
//    kLaneItems (4) items does too (its items are one run of items()): the
//    SAH splits pairs and triples the leaf cull (four items a pass) answers
//    at once, so a lane and a cull pass replace a node test and up to four
//    one-item passes. Without a cull the merged items would each be visited,
//    and that measured slower, so those trees keep the binary leaves. Each
//    wide level eats at least one binary level, so the depth is at most the
//    binary tree's (Bvh::kMaxDepth).
//  * Width, chosen at run time: eight where the CPU has AVX2
//    (__builtin_cpu_supports, once), else four; the firmware and other
//    non-x86 builds have only the 4-wide form (LATTICE_WIDE8 is 0 there, so
//    their code is what it was). The 8-wide walks carry target("avx2") and
//    flatten, which inlines the walk, the slab test and the caller's visitor
//    into one AVX2 function (GCC inlines no target-specific function into
//    a caller without that target, so a plain inline left a call per node).
//    "fma" is not enabled, so the inlined visitors round as before.
//  * Boxes rounded outwards to float, and the slab test's own rounding
//    only widening, so every item whose box the exact test reaches is
//    visited: the culling is conservative, never lossy.
//  * Nearest first: the children a node's test keeps are pushed farthest
//    first, so the nearest pops next; an entry whose (lower-bound) distance
//    is at or beyond the caller's limit is skipped when popped. Two items
//    entering at exactly the same distance are answered by whichever is
//    visited first, which depends on the grouping of the nodes: the 8-wide
//    walk may pick the other one of such a tie than the 4-wide walk (as the
//    4-wide walk may than the binary one); the goldens show no such tie.
//  * Stack: a node pushes at most W entries and pops one, so the stack
//    never holds more than (W - 1) * depth + 1 entries; kStack is 4 *
//    kMaxDepth, kStack8 8 * kMaxDepth.
#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "render/accel/bvh.hpp"
#include "render/accel/wide_slab.hpp"
#include "render/accel/wide_slab8.hpp"

namespace lattice {

// The node width a WideBvh is built with: Auto (Eight where eightWideRuns(),
// else Four), Four, or Eight (taken as Four where the CPU cannot run it).
enum class WideForm { Auto, Four, Eight };
// For tests and benchmarks: the form Auto stands for from now on.
void setWideForm(WideForm form);
// Whether the 8-wide walks can run here (x86-64 with AVX2).
bool eightWideRuns();
// What a tree built now with `form` gets: Four or Eight.
WideForm resolveWideForm(WideForm form);

// How a leaf's items are answered: Visited (each one the walk reaches), or
// Culled (four at a time by the caller's keep(): render/accel/oriented_cull.hpp).
enum class LeafItems { Visited, Culled };

template <typename T>
class WideBvh {
 public:
  struct Node {
    static constexpr int kLanes = 4;
    BoxLanes lanes;
    std::uint32_t ref[4] = {};    // inner lane: wide node index; leaf lane: first entry of items()
    std::uint32_t count[4] = {};  // leaf lane: number of items; inner lane: 0
    unsigned used = 0;            // bit n set when lane n holds a child
  };
#if LATTICE_WIDE8
  // The same for eight lanes. A binary leaf holds four items or fewer except
  // at the depth cap, where it takes whatever is left (hundreds of items for
  // boxes spaced exponentially), so the counts are full words.
  struct Node8 {
    static constexpr int kLanes = 8;
    BoxLanes8 lanes;
    std::uint32_t ref[8] = {};
    std::uint32_t count[8] = {};
    unsigned used = 0;
  };
#endif

  WideBvh() = default;
  // boxes[n] is the box of item n; every box must be finite and non-empty.
  // `threads`: the binary tree's (render/accel/bvh.hpp); the same tree at every count.
  explicit WideBvh(const std::vector<Bounds<T>>& boxes, WideForm form = WideForm::Auto,
                   LeafItems leaves = LeafItems::Visited, unsigned threads = 1);

  bool empty() const { return nodes_.empty() && nodes8Empty(); }
  WideForm form() const { return nodes8Empty() ? WideForm::Four : WideForm::Eight; }
  // The 4-wide nodes (empty when the tree is 8-wide).
  const std::vector<Node>& nodes() const { return nodes_; }
#if LATTICE_WIDE8
  // The 8-wide nodes (empty when the tree is 4-wide).
  const std::vector<Node8>& nodes8() const { return nodes8_; }
#endif
  const std::vector<std::uint32_t>& items() const { return items_; }
  int depth() const { return depth_; }
  // The binary tree's depth it was collapsed from (for the tests).
  int binaryDepth() const { return binaryDepth_; }

  // Calls visit(item) for every item whose box may meet the segment
  // (tmin, tmax), in no particular order; stops early when visit returns
  // true. Returns whether it stopped.
  template <typename Visit>
  bool visitAll(const Ray<T>& ray, T tmin, T tmax, Visit&& visit) const {
    return visitAll(ray, tmin, tmax, visit, KeepAll{});
  }
  // The same, a leaf's items first put to keep(first, count, tmin, limit),
  // which returns bit k set when the item at position first + k of items()
  // may answer (count <= 4; render/accel/oriented_cull.hpp).
  template <typename Visit, typename Keep>
  bool visitAll(const Ray<T>& ray, T tmin, T tmax, Visit&& visit, Keep&& keep) const {
#if LATTICE_WIDE8
    if (!nodes8_.empty()) return visitAll8(ray, tmin, tmax, visit, keep);
#endif
    return walkAll(nodes_, ray, tmin, tmax, visit, keep);
  }

  // Front to back: nearer children first; visit(item, limit) may lower
  // `limit` (the nearest hit so far), and children whose box starts at or
  // beyond it are skipped. Setting limit to tmin or below stops the walk.
  template <typename Visit>
  void visitFrontToBack(const Ray<T>& ray, T tmin, T& limit, Visit&& visit) const {
    visitFrontToBack(ray, tmin, limit, visit, KeepAll{});
  }
  // The same with a leaf's items put to keep() first (as visitAll's), with
  // the limit of the moment: it may only shrink while they are visited.
  template <typename Visit, typename Keep>
  void visitFrontToBack(const Ray<T>& ray, T tmin, T& limit, Visit&& visit, Keep&& keep) const {
#if LATTICE_WIDE8
    if (!nodes8_.empty()) return visitFrontToBack8(ray, tmin, limit, visit, keep);
#endif
    walkFrontToBack(nodes_, ray, tmin, limit, visit, keep);
  }

  // A node pushes at most kLanes entries and pops one.
  static constexpr int kStack = 4 * Bvh<T>::kMaxDepth;
  static constexpr int kStack8 = 8 * Bvh<T>::kMaxDepth;
  // An 8-wide leaf lane of a culled tree holds a whole binary subtree of at most
  // this many items (one leaf cull pass; 8 measured slower on Plate 6,
  // bench/results/2026-12-04-bvh8.md).
  static constexpr std::uint32_t kLaneItems = 4;

 private:
  struct KeepAll {
    unsigned operator()(std::uint32_t, std::uint32_t, T, T) const { return ~0u; }
  };
  template <typename Keep>
  static constexpr bool kKeepsAll = std::is_same_v<std::decay_t<Keep>, KeepAll>;

  // The two walks over nodes of either width, inlined into their callers so
  // the 8-wide callers compile them (and the slab test) for AVX2.
  template <typename NodeT, typename Visit, typename Keep>
  [[gnu::always_inline]] bool walkAll(const std::vector<NodeT>& nodes, const Ray<T>& ray, T tmin, T tmax,
                                      Visit& visit, Keep& keep) const {
    constexpr int kLanes = NodeT::kLanes;
    if (nodes.empty()) return false;
    const WideRay wray = wideRayFor(nodes.front().lanes, ray);
    const float t0 = floatBelow(tmin), t1 = floatAbove(tmax);
    std::uint32_t stack[kLanes * Bvh<T>::kMaxDepth];
    int top = 0;
    stack[top++] = 0;
    float entry[kLanes];
    while (top > 0) {
      const NodeT& node = nodes[stack[--top]];
      unsigned hit = slabTestLanes(node.lanes, wray, t0, t1, entry) & node.used;
      for (unsigned lane = 0; hit != 0; ++lane, hit >>= 1) {
        if (!(hit & 1u)) continue;
        const std::uint32_t count = node.count[lane];
        if (count == 0) {
          stack[top++] = node.ref[lane];
          continue;
        }
        if constexpr (kKeepsAll<Keep>) {  // no cull: the plain loop (the firmware counts its instructions)
          for (std::uint32_t n = 0; n < count; ++n)
            if (visit(items_[node.ref[lane] + n])) return true;
        } else {
          for (std::uint32_t n = 0; n < count; n += 4) {
            const std::uint32_t first = node.ref[lane] + n, group = std::min<std::uint32_t>(4, count - n);
            const unsigned kept = keep(first, group, tmin, tmax);
            for (std::uint32_t k = 0; k < group; ++k)
              if ((kept >> k & 1u) && visit(items_[first + k])) return true;
          }
        }
      }
    }
    return false;
  }

  template <typename NodeT, typename Visit, typename Keep>
  [[gnu::always_inline]] void walkFrontToBack(const std::vector<NodeT>& nodes, const Ray<T>& ray, T tmin, T& limit,
                                              Visit& visit, Keep& keep) const {
    constexpr int kLanes = NodeT::kLanes;
    if (nodes.empty()) return;
    struct Entry {
      std::uint32_t ref, count;
      float t;
    };
    const WideRay wray = wideRayFor(nodes.front().lanes, ray);
    const float t0 = floatBelow(tmin);
    Entry stack[kLanes * Bvh<T>::kMaxDepth];
    int top = 0;
    stack[top++] = {0, 0, t0};
    float entry[kLanes];
    while (top > 0) {
      const Entry e = stack[--top];
      if (!(T(e.t) < limit)) continue;  // starts at or beyond the nearest hit found since it was pushed
      if (e.count > 0) {
        if constexpr (kKeepsAll<Keep>) {
          for (std::uint32_t n = 0; n < e.count; ++n) {
            visit(items_[e.ref + n], limit);
            if (!(limit > tmin)) return;
          }
        } else {
          for (std::uint32_t n = 0; n < e.count; n += 4) {
            const std::uint32_t first = e.ref + n, count = std::min<std::uint32_t>(4, e.count - n);
            const unsigned kept = keep(first, count, tmin, limit);
            for (std::uint32_t k = 0; k < count; ++k) {
              if (!(kept >> k & 1u)) continue;
              visit(items_[first + k], limit);
              if (!(limit > tmin)) return;
            }
          }
        }
        continue;
      }
      const NodeT& node = nodes[e.ref];
      unsigned hit = slabTestLanes(node.lanes, wray, t0, floatAbove(limit), entry) & node.used;
      // Insert each kept child into the pushed run in descending distance (on a
      // tie the lower lane pops first, as the binary walk took the left child).
      const int base = top;
      for (unsigned lane = 0; hit != 0; ++lane, hit >>= 1) {
        if (!(hit & 1u)) continue;
        Entry c{node.ref[lane], node.count[lane], entry[lane]};
        int k = top++;
        for (; k > base && stack[k - 1].t <= c.t; --k) stack[k] = stack[k - 1];
        stack[k] = c;
      }
    }
  }

#if LATTICE_WIDE8
  // The 8-wide walks: compiled for AVX2 and reached only when the tree was
  // built 8-wide, which needs eightWideRuns().
  template <typename Visit, typename Keep>
  __attribute__((target("avx2"), flatten)) bool visitAll8(const Ray<T>& ray, T tmin, T tmax, Visit& visit,
                                                 Keep& keep) const {
    return walkAll(nodes8_, ray, tmin, tmax, visit, keep);
  }
  template <typename Visit, typename Keep>
  __attribute__((target("avx2"), flatten)) void visitFrontToBack8(const Ray<T>& ray, T tmin, T& limit, Visit& visit,
                                                         Keep& keep) const {
    walkFrontToBack(nodes8_, ray, tmin, limit, visit, keep);
  }
  bool nodes8Empty() const { return nodes8_.empty(); }
#else
  bool nodes8Empty() const { return true; }
#endif

  template <typename NodeT>
  std::uint32_t collapse(std::vector<NodeT>& out, const Bvh<T>& binary, const std::vector<std::uint32_t>& sizes,
                         std::uint32_t index, int depth);

  std::vector<Node> nodes_;
#if LATTICE_WIDE8
  std::vector<Node8> nodes8_;
#endif
  std::vector<std::uint32_t> items_;
  int depth_ = 0;
  int binaryDepth_ = 0;
};

extern template class WideBvh<float>;
extern template class WideBvh<double>;

// The tree a union keeps its finite children in: wide for float and double,
// binary for fixed point. Both offer visitAll and visitFrontToBack.
template <typename T>
using UnionBvh = std::conditional_t<std::is_floating_point_v<T>, WideBvh<T>, Bvh<T>>;

}  // namespace lattice
