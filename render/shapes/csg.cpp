// CSG nodes: span-list merging (render/shapes/span_ops.hpp) with box pruning at
// every node, and unions over a BVH.
#include "render/shapes/csg.hpp"

#include <algorithm>

#include "render/accel/wide_bvh.hpp"
#include "render/shapes/span_ops.hpp"
#include "render/shapes/union_core.hpp"
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

// Inside any child. Children with finite boxes live in a BVH (4- or 8-wide with
// float boxes for float and double, binary for fixed point: UnionBvh), the
// others (half-spaces, cylinders...) in a flat list that every ray visits.
// The queries are render/shapes/union_core.hpp's.
template <typename T>
class UnionNode final : public UnionCore<T, UnionNode<T>, CsgNode<T>> {
  using Core = UnionCore<T, UnionNode<T>, CsgNode<T>>;

 public:
  // `threads`: the BVH's build's (render/accel/bvh.hpp).
  UnionNode(std::vector<PrimitivePtr<T>> children, unsigned threads) : Core(std::move(children)) {
    std::vector<Bounds<T>> boxes;
    std::vector<std::uint32_t> finiteIndex;
    // Sized once: grown by doubling, the boxes of a 5000-instance scatter
    // held 8192 slots while its BVH was built (docs/memory.md).
    boxes.reserve(this->children_.size());
    finite_.reserve(this->children_.size());
    finiteIndex.reserve(this->children_.size());
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
    if (finite_.size() <= 2) {
      // One or two bounded children (a shape over a floor; the fuzzy
      // sphere's skin and its scatter of hairs): a tree of them is one node,
      // whose set-up and box test every ray paid before asking children that
      // test their own boxes anyway, so they join the list, after the
      // unbounded ones as the tree came after them, and are asked in order.
      for (std::uint32_t n : finiteIndex) unbounded_.push_back(n);
      finite_.clear();
      boxes.clear();
    }
    if constexpr (std::is_floating_point_v<T>) {
      bvh_ = UnionBvh<T>(boxes, WideForm::Auto, cullRuns() ? LeafItems::Culled : LeafItems::Visited, threads);
      keepOrientedBoxes();
    } else {
      bvh_ = UnionBvh<T>(boxes, threads);
    }
  }

  // What UnionCore asks.
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
  std::size_t unboundedCount() const { return unbounded_.size(); }
  template <typename F>
  decltype(auto) withUnbounded(std::size_t k, F f) const {
    return f(*this->children_[unbounded_[k]]);
  }
  const UnionBvh<T>& bvh() const { return bvh_; }
  template <typename F>
  decltype(auto) withItem(std::uint32_t item, F f) const {
    return f(*finite_[item]);
  }
  const OrientedCull<T>* cull() const { return cull_.empty() ? nullptr : &cull_; }
  // A cut box may stop a ray that a child blocks outside it.
  bool childrenAnswerAlone() const { return !this->limited_; }

 private:
  // The children's oriented boxes in the BVH's item order, kept only where
  // the path in use reads them (render/accel/oriented_cull.hpp) and some
  // child has one: 120 bytes an item in double, 60 in float.
  // Whether the leaves will be culled: the path in use reads the rows and some
  // child has an oriented box (the BVH then groups small subtrees for it).
  bool cullRuns() const {
    const CullPath path = activeCullPath();
    const bool lanesRun = path == CullPath::Lanes && (!std::is_same_v<T, double> || doubleLanesRun());
    if (!(path == CullPath::Portable || lanesRun)) return false;
    OrientedBox<T> probe;
    for (const Primitive<T>* child : finite_)
      if (child->orientedBox(probe)) return true;
    return false;
  }
  void keepOrientedBoxes() {
    if (!cullRuns()) return;
    const auto& items = bvh_.items();
    // Each box is read again rather than held twice (a scatter of 5000
    // lattices: 600 KB a copy). The children lie in memory in the order they
    // were built and are read in the tree's: the child kAhead items on is
    // fetched while this one is read (its first kLines lines: a lattice leaf
    // is 312 bytes).
    constexpr std::uint32_t kAhead = 8, kLines = 5;
    cull_ = OrientedCull<T>(static_cast<std::uint32_t>(items.size()), [&](std::uint32_t p, OrientedBox<T>& box) {
      if (p + kAhead < items.size())
        for (std::uint32_t line = 0; line < kLines; ++line)
          __builtin_prefetch(reinterpret_cast<const char*>(finite_[items[p + kAhead]]) + 64 * line);
      return finite_[items[p]]->orientedBox(box);
    });
  }

  UnionBvh<T> bvh_;
  OrientedCull<T> cull_;  // empty: every item the walk reaches is visited
  std::vector<const Primitive<T>*> finite_;  // BVH item -> child
  std::vector<std::uint32_t> unbounded_;  // children every ray visits: the unbounded ones, and one or two bounded ones
};

template <typename T>
std::unique_ptr<CsgNode<T>> makeNode(CsgOp op, std::vector<PrimitivePtr<T>> children, unsigned threads = 1) {
  if (children.empty())
    throw Error(ErrorKind::Input, "CSG node without children: union, intersection and difference need at least one");
  for (const auto& c : children)
    if (!c) throw Error(ErrorKind::Internal, "CSG node given a null child");
  switch (op) {
    case CsgOp::Union: return std::make_unique<UnionNode<T>>(std::move(children), threads);
    case CsgOp::Intersection: return std::make_unique<IntersectionNode<T>>(std::move(children));
    case CsgOp::Difference: return std::make_unique<DifferenceNode<T>>(std::move(children));
  }
  throw Error(ErrorKind::Internal, "unknown CSG operation");
}

}  // namespace

template <typename T>
PrimitivePtr<T> makeCsgNode(CsgOp op, std::vector<PrimitivePtr<T>> children, unsigned threads) {
  return makeNode(op, std::move(children), threads);
}

template <typename T>
PrimitivePtr<T> makeCsgNode(CsgOp op, std::vector<PrimitivePtr<T>> children, const Bounds<T>& limit) {
  auto node = makeNode(op, std::move(children));
  node->limitBounds(limit);
  return node;
}

#define LATTICE_INSTANTIATE(T) \
  template PrimitivePtr<T> makeCsgNode<T>(CsgOp, std::vector<PrimitivePtr<T>>, unsigned); \
  template PrimitivePtr<T> makeCsgNode<T>(CsgOp, std::vector<PrimitivePtr<T>>, const Bounds<T>&);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
