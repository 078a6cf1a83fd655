// CSG nodes: span-list merging (render/shapes/span_ops.hpp) with box pruning at
// every node, and unions over a BVH.
#include "render/shapes/csg.hpp"

#include <algorithm>

#include "render/accel/wide_bvh.hpp"
#include "render/shapes/span_ops.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

namespace {

template <typename T>
Bounds<T> intersectBoxes(const Bounds<T>& a, const Bounds<T>& b) {
  return {componentMax(a.lo, b.lo), componentMin(a.hi, b.hi)};
}

template <typename T>
class CsgNode : public Primitive<T> {
 public:
  explicit CsgNode(std::vector<PrimitivePtr<T>> children) : children_(std::move(children)) {}
  const Bounds<T>& bounds() const override { return bounds_; }
  void limitBounds(const Bounds<T>& limit) {
    bounds_ = intersectBoxes(bounds_, limit);
    limited_ = true;
  }

 protected:
  // Intersection and difference fold their children into the first child's
  // spans with `merge`. Once the running result is empty nothing can bring it
  // back, and each later child is asked only about the part of the ray still
  // in play. A child the ray misses is passed to `merge` as an empty list
  // unless `skipMissed` (for difference, subtracting nothing changes nothing).
  template <typename Merge>
  void foldChildren(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out, Merge merge, bool skipMissed) const {
    T t0, t1;
    if (bounds_.empty() || !bounds_.clip(ray, tmin, tmax, t0, t1)) return;
    SpanList<T> acc, child, next;
    children_[0]->spans(ray, tmin, tmax, acc);
    for (std::size_t n = 1; n < children_.size() && !acc.empty(); ++n) {
      T lo = std::max(tmin, acc[0].enter.t), hi = std::min(tmax, acc.back().leave.t);
      child.clear();
      if (children_[n]->bounds().clip(ray, lo, hi, t0, t1)) children_[n]->spans(ray, lo, hi, child);
      if (skipMissed && child.empty()) continue;
      next.clear();
      merge(acc, child, next);
      acc = next;
    }
    keepOverlapping(acc, tmin, tmax);
    for (const Span<T>& s : acc) out.push_back(s);
  }

  std::vector<PrimitivePtr<T>> children_;
  Bounds<T> bounds_;
  bool limited_ = false;  // bounds_ cut by a box the caller gave (limitBounds)
};

// Inside every child. A ray that leaves the running result empty stops; each
// later child is only asked about the part of the ray still in play.
template <typename T>
class IntersectionNode final : public CsgNode<T> {
 public:
  explicit IntersectionNode(std::vector<PrimitivePtr<T>> children) : CsgNode<T>(std::move(children)) {
    this->bounds_ = Bounds<T>::infinite();
    for (const auto& c : this->children_) this->bounds_ = intersectBoxes(this->bounds_, c->bounds());
  }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    this->foldChildren(ray, tmin, tmax, out, intersectSpans<T>, /*skipMissed=*/false);
  }
};

// Inside the first child and outside all the others.
template <typename T>
class DifferenceNode final : public CsgNode<T> {
 public:
  explicit DifferenceNode(std::vector<PrimitivePtr<T>> children) : CsgNode<T>(std::move(children)) {
    this->bounds_ = this->children_[0]->bounds();
  }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    this->foldChildren(ray, tmin, tmax, out, subtractSpans<T>, /*skipMissed=*/true);
  }
};

// Inside any child. Children with finite boxes live in a BVH (4-wide with
// float boxes for float and double, binary for fixed point: UnionBvh), the
// others (half-spaces, cylinders...) in a flat list that every ray visits.
template <typename T>
class UnionNode final : public CsgNode<T> {
 public:
  explicit UnionNode(std::vector<PrimitivePtr<T>> children) : CsgNode<T>(std::move(children)) {
    std::vector<Bounds<T>> boxes;
    std::vector<std::uint32_t> finiteIndex;
    for (std::uint32_t n = 0; n < this->children_.size(); ++n) {
      const Bounds<T>& b = this->children_[n]->bounds();
      if (b.empty()) continue;  // an empty solid adds nothing
      this->bounds_.extend(b);
      if (b.isFinite()) {
        boxes.push_back(b);
        finite_.push_back(this->children_[n].get());
        finiteIndex.push_back(n);
      } else {
        unbounded_.push_back(n);
      }
    }
    if (finite_.size() == 1) {
      // One bounded child (a shape over a floor): its own box test is all a
      // tree would do, so it joins the list, after the unbounded ones as the
      // tree came after them.
      unbounded_.push_back(finiteIndex[0]);
      finite_.clear();
      boxes.clear();
    }
    bvh_ = UnionBvh<T>(boxes);
  }

  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    if (outsideBox(ray, tmin, tmax)) return;
    SpanList<T> all;
    auto add = [&](const Primitive<T>& child) {
      SpanList<T> list;
      child.spans(ray, tmin, tmax, list);
      for (const Span<T>& s : list) all.push_back(s);
    };
    for (std::uint32_t n : unbounded_) add(*this->children_[n]);
    bvh_.visitAll(ray, tmin, tmax, [&](std::uint32_t item) {
      add(*finite_[item]);
      return false;
    });
    coalesceSpans(all);
    for (const Span<T>& s : all) out.push_back(s);
  }

  // Front to back with early termination. While no child contains the ray at
  // tmin, the union's first crossing is the earliest enter of any child, so
  // subtrees starting beyond the best enter so far are skipped. A ray that
  // starts inside a child (rare: shadow rays start on surfaces, cameras
  // outside) takes the exact path through spans().
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
    if (outsideBox(ray, tmin, tmax)) return false;
    T limit = tmax;
    bool found = false;
    Hit<T> child;
    auto visit = [&](const Primitive<T>& c, T& lim) {
      if (inside) return;
      if (c.firstEnter(ray, tmin, lim, child, inside)) {
        lim = child.t;
        hit = child;
        found = true;
      }
      if (inside) lim = tmin;  // stops the traversal
    };
    for (std::uint32_t n : unbounded_) visit(*this->children_[n], limit);
    if (!inside)
      bvh_.visitFrontToBack(ray, tmin, limit, [&](std::uint32_t item, T& lim) { visit(*finite_[item], lim); });
    return found && !inside;
  }

  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    if (outsideBox(ray, tmin, tmax)) return false;
    for (std::uint32_t n : unbounded_)
      if (this->children_[n]->anyHit(ray, tmin, tmax)) return true;
    // In tree order, not nearest first: with a handful of children per shadow
    // ray, sorting them cost as much as it saved (docs/benchmarks.md, Step 4).
    return bvh_.visitAll(ray, tmin, tmax, [&](std::uint32_t item) { return finite_[item]->anyHit(ray, tmin, tmax); });
  }

 private:
  // Where the union's box is just the union of its children's boxes and all
  // of them are in the tree, the tree's first node tests those same boxes,
  // so testing the union's box first would only repeat the work (three
  // divisions a ray). It decides where the box was cut (limitBounds) or an
  // unbounded child is listed.
  bool outsideBox(const Ray<T>& ray, T tmin, T tmax) const {
    if (this->bounds_.empty()) return true;
    if (!this->limited_ && unbounded_.empty()) return false;
    T t0, t1;
    return !this->bounds_.clip(ray, tmin, tmax, t0, t1);
  }

  UnionBvh<T> bvh_;
  std::vector<const Primitive<T>*> finite_;  // BVH item -> child
  std::vector<std::uint32_t> unbounded_;  // children every ray visits: the unbounded ones, or a lone bounded one
};

template <typename T>
std::unique_ptr<CsgNode<T>> makeNode(CsgOp op, std::vector<PrimitivePtr<T>> children) {
  if (children.empty())
    throw Error(ErrorKind::Input, "CSG node without children: union, intersection and difference need at least one");
  for (const auto& c : children)
    if (!c) throw Error(ErrorKind::Internal, "CSG node given a null child");
  switch (op) {
    case CsgOp::Union: return std::make_unique<UnionNode<T>>(std::move(children));
    case CsgOp::Intersection: return std::make_unique<IntersectionNode<T>>(std::move(children));
    case CsgOp::Difference: return std::make_unique<DifferenceNode<T>>(std::move(children));
  }
  throw Error(ErrorKind::Internal, "unknown CSG operation");
}

}  // namespace

template <typename T>
PrimitivePtr<T> makeCsgNode(CsgOp op, std::vector<PrimitivePtr<T>> children) {
  return makeNode(op, std::move(children));
}

template <typename T>
PrimitivePtr<T> makeCsgNode(CsgOp op, std::vector<PrimitivePtr<T>> children, const Bounds<T>& limit) {
  auto node = makeNode(op, std::move(children));
  node->limitBounds(limit);
  return node;
}

#define LATTICE_INSTANTIATE(T) \
  template PrimitivePtr<T> makeCsgNode<T>(CsgOp, std::vector<PrimitivePtr<T>>); \
  template PrimitivePtr<T> makeCsgNode<T>(CsgOp, std::vector<PrimitivePtr<T>>, const Bounds<T>&);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
