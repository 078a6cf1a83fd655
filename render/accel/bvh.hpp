#pragma once
// A bounding volume hierarchy over the finite boxes of a union's children, so
// a ray costs about log N box tests instead of N (a union of 5000 hairs is a
// normal scene). Built top-down with the surface area heuristic over binned
// centroids [MacDonald & Booth 1990]; children with infinite boxes are kept
// out of it by the caller (their box would cover every node).
//
// A tree may also be a view of nodes and items built elsewhere (a baked
// scene's constant arrays in flash, docs/firmware.md): Bvh::view, traversed
// by the same code, so a view answers as the tree it was built from.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "foundation/bounds.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

// Slab test with the reciprocal direction taken once per walk, not once per
// box (the BVH tests dozens of boxes per ray); in fixed point the ray keeps it
// for every other box test of the ray too (foundation/ray.hpp). BVH
// boxes are finite; a zero direction component gives infinite reciprocals,
// and the NaN of 0 * inf (origin exactly on a slab) keeps the segment, which
// errs on the side of visiting the box.
template <typename T>
struct SlabTest {
  Vec3<T> origin, inverse;
  explicit SlabTest(const Ray<T>& ray) : origin(ray.origin), inverse(ray.inverseDirection()) {}
  bool clip(const Bounds<T>& b, T tmin, T tmax, T& t0) const {
    for (int a = 0; a < 3; ++a) {
      T ta = (b.lo[a] - origin[a]) * inverse[a], tb = (b.hi[a] - origin[a]) * inverse[a];
      if (ta > tb) std::swap(ta, tb);
      tmin = ta > tmin ? ta : tmin;
      tmax = tb < tmax ? tb : tmax;
      if (tmin > tmax) return false;
    }
    t0 = tmin;
    return true;
  }
};

template <typename T>
class Bvh {
 public:
  struct Node {
    Bounds<T> box;
    std::uint32_t first = 0;  // leaf: first entry of items(); inner: index of the right child
    std::uint32_t count = 0;  // leaf: number of items; inner: 0 (left child is the next node)
  };

  Bvh() = default;
  // boxes[n] is the box of item n; every box must be finite and non-empty.
  // `threads`: the two subtrees of the top splits are built at once on up to
  // this many; the tree is the same at every count.
  explicit Bvh(const std::vector<Bounds<T>>& boxes, unsigned threads = 1);

  // A tree over nodes and items that outlive it (constant data): what
  // nodes() and items() of a built tree held.
  static Bvh view(std::span<const Node> nodes, std::span<const std::uint32_t> items, int depth) {
    Bvh b;
    b.viewNodes_ = nodes;
    b.viewItems_ = items;
    b.depth_ = depth;
    return b;
  }

  bool empty() const { return nodeSpan().empty(); }
  std::span<const Node> nodes() const { return nodeSpan(); }
  std::span<const std::uint32_t> items() const { return itemSpan(); }
  int depth() const { return depth_; }

  // Calls visit(item) for every item whose box the segment (tmin, tmax)
  // touches, in no particular order; stops early when visit returns true.
  // Returns whether it stopped.
  template <typename Visit>
  bool visitAll(const Ray<T>& ray, T tmin, T tmax, Visit&& visit) const {
    const std::span<const Node> nodes = nodeSpan();
    const std::span<const std::uint32_t> items = itemSpan();
    if (nodes.empty()) return false;
    const SlabTest<T> slab(ray);
    std::uint32_t stack[kMaxDepth];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes[stack[--top]];
      T t0;
      if (!slab.clip(node.box, tmin, tmax, t0)) continue;
      if (node.count > 0) {
        for (std::uint32_t n = 0; n < node.count; ++n)
          if (visit(items[node.first + n])) return true;
      } else {
        std::uint32_t self = static_cast<std::uint32_t>(&node - nodes.data());
        stack[top++] = node.first;
        stack[top++] = self + 1;
      }
    }
    return false;
  }

  // Front to back: nearer subtrees first; visit(item, limit) may lower
  // `limit` (the nearest hit so far), and subtrees whose box starts at or
  // beyond limit are skipped.
  template <typename Visit>
  void visitFrontToBack(const Ray<T>& ray, T tmin, T& limit, Visit&& visit) const {
    const std::span<const Node> nodes = nodeSpan();
    const std::span<const std::uint32_t> items = itemSpan();
    if (nodes.empty()) return;
    struct Entry {
      std::uint32_t node;
      T t;
    };
    const SlabTest<T> slab(ray);
    Entry stack[kMaxDepth];
    int top = 0;
    T t0;
    if (!slab.clip(nodes[0].box, tmin, limit, t0)) return;
    stack[top++] = {0, t0};
    while (top > 0) {
      Entry e = stack[--top];
      if (e.t >= limit) continue;  // starts beyond the nearest hit found since it was pushed
      const Node& node = nodes[e.node];
      if (node.count > 0) {
        for (std::uint32_t n = 0; n < node.count; ++n) visit(items[node.first + n], limit);
        continue;
      }
      std::uint32_t left = e.node + 1, right = node.first;
      T l0 = T(0), r0 = T(0);
      bool hitL = slab.clip(nodes[left].box, tmin, limit, l0);
      bool hitR = slab.clip(nodes[right].box, tmin, limit, r0);
      if (hitL && hitR) {
        // Push the farther one first so the nearer one is popped next.
        if (l0 <= r0) {
          stack[top++] = {right, r0};
          stack[top++] = {left, l0};
        } else {
          stack[top++] = {left, l0};
          stack[top++] = {right, r0};
        }
      } else if (hitL) {
        stack[top++] = {left, l0};
      } else if (hitR) {
        stack[top++] = {right, r0};
      }
    }
  }

  // The build stops splitting at this depth, so the traversal stacks above
  // (at most one pending sibling per level) never overflow.
  static constexpr int kMaxDepth = 60;

 private:
  // A built tree's own arrays, or the view's (never both).
  std::span<const Node> nodeSpan() const { return viewNodes_.empty() ? std::span<const Node>(nodes_) : viewNodes_; }
  std::span<const std::uint32_t> itemSpan() const {
    return viewNodes_.empty() ? std::span<const std::uint32_t>(items_) : viewItems_;
  }

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> items_;
  std::span<const Node> viewNodes_;
  std::span<const std::uint32_t> viewItems_;
  int depth_ = 0;
};

#define LATTICE_DECLARE(T) extern template class Bvh<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
