// BVH construction: binned surface area heuristic. The expected cost of a
// split is proportional to sum over sides of (surface area x item count),
// since the chance that a ray through the parent also hits a child box is
// about the ratio of their areas.
//
// Each bin gathers its items' boxes and centroids, so a split hands each
// child the extent of its items as unions of bins (min and max, the same
// values a sweep over the child's items gives), and the partition reads back
// each item's bin instead of binning it again: one sweep over a node's items
// instead of three. Items are partitioned with their boxes beside them, so
// each sweep reads one run of memory.
//
// On threads, the two subtrees of a split are built at once, each into nodes
// of its own, then laid out after their parent as the one-thread build lays
// them (depth first, left before right): each side's split sees only its own
// range of items, so the tree is the same at every thread count.
#include "render/accel/bvh.hpp"

#include <algorithm>

#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"
#include "foundation/threads.hpp"

namespace lattice {

namespace {

template <typename T>
double halfArea(const Bounds<T>& b) {
  if (b.empty()) return 0.0;
  Vec3<double> e = Vec3<double>(b.hi) - Vec3<double>(b.lo);
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

constexpr int kBins = 12;
constexpr std::uint32_t kLeafSize = 4;
// Fewer items than this are built on one thread: starting one would cost
// more than the subtree.
constexpr std::uint32_t kParallelItems = 1024;

// The boxes' union and the centroids' bounds over a range of items.
template <typename T>
struct Extent {
  Bounds<T> box, centroids;
};

// What the build decides for the node over items [begin, end): its box, and
// whether it is a leaf or where its items were partitioned (mid). A binned
// split also gives each side's extent, gathered per bin while binning, so a
// child does not sweep its items again for them; a median split does not.
template <typename T>
struct Split {
  Bounds<T> box;
  bool leaf = false;
  std::uint32_t mid = 0;
  bool sidesKnown = false;
  Extent<T> left, right;
};

template <typename T>
struct Subtree {
  std::vector<typename Bvh<T>::Node> nodes;  // depth first; inner nodes' `first` counts from this subtree's root
  int depth = 0;
};

template <typename T>
class BvhBuilder {
 public:
  explicit BvhBuilder(const std::vector<Bounds<T>>& boxes) : boxes_(boxes), work_(boxes.size()) {
    for (std::size_t n = 0; n < boxes.size(); ++n) work_[n] = {boxes[n], static_cast<std::uint32_t>(n)};
  }

  // The items in the order the build left them: each leaf's run.
  void itemsInto(std::vector<std::uint32_t>& items) const {
    items.resize(work_.size());
    for (std::size_t n = 0; n < work_.size(); ++n) items[n] = work_[n].id;
  }

  // The subtree over items [begin, end), whose root sits at `depth`; `known`
  // is the range's extent where the parent's split gathered it (else null).
  Subtree<T> build(std::uint32_t begin, std::uint32_t end, int depth, unsigned threads, const Extent<T>* known) {
    // Without threads (the firmware) the parallel build is not compiled at all.
    if constexpr (kHasThreads)
      if (threads > 1 && end - begin >= kParallelItems) return buildParallel(begin, end, depth, threads, known);
    Subtree<T> tree;
    tree.nodes.reserve(2 * (end - begin));
    buildSerial(tree, begin, end, depth, known);
    return tree;
  }

 private:
  static const Extent<T>* leftOf(const Split<T>& split) { return split.sidesKnown ? &split.left : nullptr; }
  static const Extent<T>* rightOf(const Split<T>& split) { return split.sidesKnown ? &split.right : nullptr; }

  Subtree<T> buildParallel(std::uint32_t begin, std::uint32_t end, int depth, unsigned threads,
                           const Extent<T>* known) {
    Subtree<T> tree;
    const Split<T> split = splitAt(begin, end, depth, known);
    tree.depth = depth;
    tree.nodes.push_back({split.box, begin, end - begin});
    if (split.leaf) return tree;
    Subtree<T> left, right;
    runWorkers(
        2u,
        [&](unsigned side) {
          if (side == 0)
            left = build(begin, split.mid, depth + 1, threads / 2, leftOf(split));
          else
            right = build(split.mid, end, depth + 1, threads - threads / 2, rightOf(split));
        },
        [] {});  // each side runs to its end; an error (out of memory) reaches the caller
    const auto place = [&](const Subtree<T>& side) {
      const std::uint32_t base = static_cast<std::uint32_t>(tree.nodes.size());
      for (typename Bvh<T>::Node node : side.nodes) {
        if (node.count == 0) node.first += base;  // an inner node's right child
        tree.nodes.push_back(node);
      }
      tree.depth = std::max(tree.depth, side.depth);
    };
    tree.nodes.reserve(1 + left.nodes.size() + right.nodes.size());
    place(left);
    tree.nodes[0].first = static_cast<std::uint32_t>(tree.nodes.size());
    tree.nodes[0].count = 0;
    place(right);
    return tree;
  }

  // noipa: one copy (no clone for the caller's constants), the split inlined
  // into it where it is its one caller (the firmware, whose flash is full).
  [[gnu::noipa]] std::uint32_t buildSerial(Subtree<T>& tree, std::uint32_t begin, std::uint32_t end, int depth,
                                           const Extent<T>* known) {
    tree.depth = std::max(tree.depth, depth);
    const std::uint32_t index = static_cast<std::uint32_t>(tree.nodes.size());
    const Split<T> split = splitAt(begin, end, depth, known);
    tree.nodes.push_back({split.box, begin, end - begin});
    if (split.leaf) return index;
    buildSerial(tree, begin, split.mid, depth + 1, leftOf(split));
    const std::uint32_t right = buildSerial(tree, split.mid, end, depth + 1, rightOf(split));
    tree.nodes[index].first = right;
    tree.nodes[index].count = 0;
    return index;
  }

  // Items [begin, end) arranged about their median centroid on `axis` at
  // mid, by nth_element over their ids: the arrangement it gives the ids
  // (the same comparisons and moves whatever the element), and one
  // instantiation of it for every tree, not one per item type (the
  // firmware's flash is full).
  void medianSplit(std::uint32_t begin, std::uint32_t mid, std::uint32_t end, int axis) {
    std::vector<std::uint32_t> ids(end - begin);
    for (std::uint32_t n = begin; n < end; ++n) ids[n - begin] = work_[n].id;
    std::nth_element(ids.begin(), ids.begin() + (mid - begin), ids.end(), [&](std::uint32_t l, std::uint32_t r) {
      return boxes_[l].center()[axis] < boxes_[r].center()[axis];
    });
    for (std::uint32_t n = begin; n < end; ++n) work_[n] = {boxes_[ids[n - begin]], ids[n - begin]};
  }

  Split<T> splitAt(std::uint32_t begin, std::uint32_t end, int depth, const Extent<T>* known) {
    Split<T> result;
    Extent<T> range;
    if (known) {
      range = *known;
    } else {
      for (std::uint32_t n = begin; n < end; ++n) {
        range.box.extend(work_[n].box);
        range.centroids.extend(work_[n].box.center());
      }
    }
    result.box = range.box;
    const Bounds<T>& box = result.box;
    const Bounds<T>& cbox = range.centroids;
    const std::uint32_t count = end - begin;
    result.leaf = true;
    if (count <= 1 || depth >= Bvh<T>::kMaxDepth - 4) return result;

    int axis = 0;
    Vec3<T> extent = cbox.hi - cbox.lo;
    if (extent.y > extent[axis]) axis = 1;
    if (extent.z > extent[axis]) axis = 2;

    std::uint32_t mid = begin;
    if (extent[axis] > T(0)) {
      // Each bin gathers its items' extent, so the sides' extents are unions
      // of bins: the values a sweep over each side's items would give.
      struct Bin {
        Extent<T> extent;
        std::uint32_t count = 0;
      };
      Bin bins[kBins];
      const double lo = double(cbox.lo[axis]), scale = kBins / (double(cbox.hi[axis]) - lo);
      for (std::uint32_t n = begin; n < end; ++n) {
        Item& item = work_[n];
        const Vec3<T> centroid = item.box.center();
        int b = static_cast<int>((double(centroid[axis]) - lo) * scale);
        b = std::clamp(b, 0, kBins - 1);
        item.bin = static_cast<std::uint8_t>(b);  // the partition below reads it back
        Bin& bin = bins[b];
        bin.extent.box.extend(item.box);
        bin.extent.centroids.extend(centroid);
        ++bin.count;
      }
      // Only the bins that hold items are swept: a plane after an empty bin
      // costs exactly what the plane before it does (the same unions and
      // counts on both sides), and one before every item or after every item
      // costs more than no split, so neither is ever strictly cheaper. Small
      // nodes, most of a tree, use a few of the bins.
      int used[kBins];
      int usedCount = 0;
      for (int b = 0; b < kBins; ++b)
        if (bins[b].count > 0) used[usedCount++] = b;
      // Sweep from the right to get every suffix, then from the left.
      double rightCost[kBins];
      Bounds<T> acc;
      std::uint32_t accCount = 0;
      for (int k = usedCount - 1; k > 0; --k) {
        acc.extend(bins[used[k]].extent.box);
        accCount += bins[used[k]].count;
        rightCost[k] = halfArea(acc) * accCount;
      }
      const double nodeArea = halfArea(box);
      double bestCost = nodeArea * count;  // cost of not splitting
      int bestSplit = -1;
      acc = Bounds<T>();
      accCount = 0;
      for (int k = 0; k < usedCount - 1; ++k) {
        acc.extend(bins[used[k]].extent.box);
        accCount += bins[used[k]].count;
        // One extra box test per child makes tiny splits not worth it.
        double cost = nodeArea + halfArea(acc) * accCount + rightCost[k + 1];
        if (cost < bestCost) {
          bestCost = cost;
          bestSplit = used[k];
        }
      }
      if (bestSplit < 0 && count <= kLeafSize) return result;
      if (bestSplit >= 0) {
        Item* split = std::partition(work_.data() + begin, work_.data() + end,
                                     [&](const Item& item) { return item.bin <= bestSplit; });
        mid = static_cast<std::uint32_t>(split - work_.data());
        for (int b = 0; b < kBins; ++b) {
          Extent<T>& side = b <= bestSplit ? result.left : result.right;
          side.box.extend(bins[b].extent.box);
          side.centroids.extend(bins[b].extent.centroids);
        }
        result.sidesKnown = true;
      }
    } else if (count <= kLeafSize) {
      return result;
    }
    if (mid == begin || mid == end) {
      // SAH found nothing useful (equal centroids, or no good plane) but there
      // are too many items for a leaf: split at the median.
      mid = begin + count / 2;
      medianSplit(begin, mid, end, axis);
      result.sidesKnown = false;
    }
    result.leaf = false;
    result.mid = mid;
    return result;
  }

  // An item with its box, moved with it by each partition, so a node's items
  // are read in order and not gathered from across the boxes (the centroid is
  // the box's centre, recomputed rather than held: the build's memory is a
  // 5000-instance scatter's peak, docs/memory.md).
  struct Item {
    Bounds<T> box;
    std::uint32_t id = 0;
    std::uint8_t bin = 0;  // its bin in its node's latest binning
  };
  const std::vector<Bounds<T>>& boxes_;  // by id
  std::vector<Item> work_;  // each subtree partitions its own range only
};

}  // namespace

template <typename T>
Bvh<T>::Bvh(const std::vector<Bounds<T>>& boxes, unsigned threads) {
  if (boxes.empty()) return;
  for (const Bounds<T>& b : boxes)
    if (b.empty() || !b.isFinite())
      throw Error(ErrorKind::Internal, "BVH built over an empty or infinite box; the union must keep those apart");
  BvhBuilder<T> builder(boxes);
  Subtree<T> tree = builder.build(0, static_cast<std::uint32_t>(boxes.size()), 1, threads, nullptr);
  builder.itemsInto(items_);
  nodes_ = std::move(tree.nodes);
  depth_ = tree.depth;
}

#define LATTICE_INSTANTIATE(T) template class Bvh<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
