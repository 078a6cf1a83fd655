#pragma once
// A 4-wide BVH: the binary SAH tree of render/accel/bvh.hpp collapsed so that each
// node holds up to four children's boxes in float, tested with one 4-lane
// slab test (render/accel/wide_slab.hpp) instead of a double test per box. The
// union of a scene's children (render/shapes/csg.cpp) walks it for float and double
// rays; fixed point keeps the binary tree, whose Q31.32 boxes have no
// conservative float form without a range check per box.
//
// Method and tunables:
//  * Collapse: starting from a binary node's two children, the inner child
//    with the largest surface area is replaced by its two children until
//    there are four or only binary leaves remain (the usual collapse of a
//    binary SAH tree, as Embree's BVH4 builders and Wald et al., "Getting
//    rid of packets", 2008, describe). Binary leaves (up to 4 items) become
//    leaf lanes. Each wide level eats at least one binary level, so the
//    depth is at most the binary tree's (Bvh::kMaxDepth).
//  * Boxes rounded outwards to float, and the slab test's own rounding
//    only widening, so every item whose box the exact test reaches is
//    visited: the culling is conservative, never lossy.
//  * Nearest first: the children a node's test keeps are pushed farthest
//    first, so the nearest pops next; an entry whose (lower-bound) distance
//    is at or beyond the caller's limit is skipped when popped.
//  * Stack: a node pushes at most four entries and pops one, so the stack
//    never holds more than 3 * depth + 1 entries; kStack is 4 * kMaxDepth.
#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "render/accel/bvh.hpp"
#include "render/accel/wide_slab.hpp"

namespace lattice {

template <typename T>
class WideBvh {
 public:
  struct Node {
    BoxLanes lanes;
    std::uint32_t ref[4] = {};    // inner lane: wide node index; leaf lane: first entry of items()
    std::uint32_t count[4] = {};  // leaf lane: number of items; inner lane: 0
    unsigned used = 0;            // bit n set when lane n holds a child
  };

  WideBvh() = default;
  // boxes[n] is the box of item n; every box must be finite and non-empty.
  // `threads`: the binary tree's (render/accel/bvh.hpp); the same tree at every count.
  explicit WideBvh(const std::vector<Bounds<T>>& boxes, unsigned threads = 1);

  bool empty() const { return nodes_.empty(); }
  const std::vector<Node>& nodes() const { return nodes_; }
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
    if (nodes_.empty()) return false;
    const WideRay wray(ray);
    const float t0 = floatBelow(tmin), t1 = floatAbove(tmax);
    std::uint32_t stack[kStack];
    int top = 0;
    stack[top++] = 0;
    float entry[4];
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      unsigned hit = slabTest4(node.lanes, wray, t0, t1, entry) & node.used;
      for (unsigned lane = 0; hit != 0; ++lane, hit >>= 1) {
        if (!(hit & 1u)) continue;
        if (node.count[lane] == 0) {
          stack[top++] = node.ref[lane];
          continue;
        }
        if constexpr (kKeepsAll<Keep>) {  // no cull: the plain loop (the firmware counts its instructions)
          for (std::uint32_t n = 0; n < node.count[lane]; ++n)
            if (visit(items_[node.ref[lane] + n])) return true;
        } else {
          for (std::uint32_t n = 0; n < node.count[lane]; n += 4) {
            const std::uint32_t first = node.ref[lane] + n, count = std::min<std::uint32_t>(4, node.count[lane] - n);
            const unsigned kept = keep(first, count, tmin, tmax);
            for (std::uint32_t k = 0; k < count; ++k)
              if ((kept >> k & 1u) && visit(items_[first + k])) return true;
          }
        }
      }
    }
    return false;
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
    if (nodes_.empty()) return;
    struct Entry {
      std::uint32_t ref, count;
      float t;
    };
    const WideRay wray(ray);
    const float t0 = floatBelow(tmin);
    Entry stack[kStack];
    int top = 0;
    stack[top++] = {0, 0, t0};
    float entry[4];
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
      const Node& node = nodes_[e.ref];
      unsigned hit = slabTest4(node.lanes, wray, t0, floatAbove(limit), entry) & node.used;
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

  static constexpr int kStack = 4 * Bvh<T>::kMaxDepth;

 private:
  struct KeepAll {
    unsigned operator()(std::uint32_t, std::uint32_t, T, T) const { return ~0u; }
  };
  template <typename Keep>
  static constexpr bool kKeepsAll = std::is_same_v<std::decay_t<Keep>, KeepAll>;

  std::uint32_t collapse(const Bvh<T>& binary, std::uint32_t index, int depth);

  std::vector<Node> nodes_;
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
