// BVH construction: binned surface area heuristic. The expected cost of a
// split is proportional to sum over sides of (surface area x item count),
// since the chance that a ray through the parent also hits a child box is
// about the ratio of their areas.
//
// On threads, the two subtrees of a split are built at once, each into nodes
// of its own, then laid out after their parent as the one-thread build lays
// them (depth first, left before right): each side's split sees only its own
// range of items, so the tree is the same at every thread count.
#include "render/accel/bvh.hpp"

#include <algorithm>
#include <numeric>

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

// What the build decides for the node over items [begin, end): its box, and
// whether it is a leaf or where its items were partitioned (mid).
template <typename T>
struct Split {
  Bounds<T> box;
  bool leaf = false;
  std::uint32_t mid = 0;
};

template <typename T>
struct Subtree {
  std::vector<typename Bvh<T>::Node> nodes;  // depth first; inner nodes' `first` counts from this subtree's root
  int depth = 0;
};

template <typename T>
class BvhBuilder {
 public:
  BvhBuilder(std::vector<std::uint32_t>& items, const std::vector<Bounds<T>>& boxes)
      : items_(items), boxes_(boxes), centroids_(boxes.size()) {
    // Points, not boxes of zero size: half the bytes while the tree is built,
    // the build's peak on a 5000-instance scatter (docs/memory.md).
    for (std::size_t n = 0; n < boxes.size(); ++n) centroids_[n] = boxes[n].center();
  }

  // The subtree over items [begin, end), whose root sits at `depth`.
  Subtree<T> build(std::uint32_t begin, std::uint32_t end, int depth, unsigned threads) const {
    // Without threads (the firmware) the parallel build is not compiled at all.
    if constexpr (kHasThreads)
      if (threads > 1 && end - begin >= kParallelItems) return buildParallel(begin, end, depth, threads);
    Subtree<T> tree;
    tree.nodes.reserve(2 * (end - begin));
    buildSerial(tree, begin, end, depth);
    return tree;
  }

 private:
  Subtree<T> buildParallel(std::uint32_t begin, std::uint32_t end, int depth, unsigned threads) const {
    Subtree<T> tree;
    const Split<T> split = splitAt(begin, end, depth);
    tree.depth = depth;
    tree.nodes.push_back({split.box, begin, end - begin});
    if (split.leaf) return tree;
    Subtree<T> left, right;
    runWorkers(
        2u,
        [&](unsigned side) {
          if (side == 0)
            left = build(begin, split.mid, depth + 1, threads / 2);
          else
            right = build(split.mid, end, depth + 1, threads - threads / 2);
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
  [[gnu::noipa]] std::uint32_t buildSerial(Subtree<T>& tree, std::uint32_t begin, std::uint32_t end, int depth) const {
    tree.depth = std::max(tree.depth, depth);
    const std::uint32_t index = static_cast<std::uint32_t>(tree.nodes.size());
    const Split<T> split = splitAt(begin, end, depth);
    tree.nodes.push_back({split.box, begin, end - begin});
    if (split.leaf) return index;
    buildSerial(tree, begin, split.mid, depth + 1);
    const std::uint32_t right = buildSerial(tree, split.mid, end, depth + 1);
    tree.nodes[index].first = right;
    tree.nodes[index].count = 0;
    return index;
  }

  Split<T> splitAt(std::uint32_t begin, std::uint32_t end, int depth) const {
    Split<T> result;
    Bounds<T> cbox;
    for (std::uint32_t n = begin; n < end; ++n) {
      result.box.extend(boxes_[items_[n]]);
      cbox.extend(centroids_[items_[n]]);
    }
    const Bounds<T>& box = result.box;
    const std::uint32_t count = end - begin;
    result.leaf = true;
    if (count <= 1 || depth >= Bvh<T>::kMaxDepth - 4) return result;

    int axis = 0;
    Vec3<T> extent = cbox.hi - cbox.lo;
    if (extent.y > extent[axis]) axis = 1;
    if (extent.z > extent[axis]) axis = 2;

    std::uint32_t mid = begin;
    if (extent[axis] > T(0)) {
      struct Bin {
        Bounds<T> box;
        std::uint32_t count = 0;
      };
      Bin bins[kBins];
      const double lo = double(cbox.lo[axis]), scale = kBins / (double(cbox.hi[axis]) - lo);
      auto binOf = [&](std::uint32_t item) {
        int b = static_cast<int>((double(centroids_[item][axis]) - lo) * scale);
        return std::clamp(b, 0, kBins - 1);
      };
      for (std::uint32_t n = begin; n < end; ++n) {
        Bin& bin = bins[binOf(items_[n])];
        bin.box.extend(boxes_[items_[n]]);
        ++bin.count;
      }
      // Sweep from the right to get every suffix, then from the left.
      double rightCost[kBins];
      Bounds<T> acc;
      std::uint32_t accCount = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.extend(bins[b].box);
        accCount += bins[b].count;
        rightCost[b] = halfArea(acc) * accCount;
      }
      double bestCost = halfArea(box) * count;  // cost of not splitting
      int bestSplit = -1;
      acc = Bounds<T>();
      accCount = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.extend(bins[b].box);
        accCount += bins[b].count;
        // One extra box test per child makes tiny splits not worth it.
        double cost = halfArea(box) + halfArea(acc) * accCount + rightCost[b + 1];
        if (cost < bestCost) {
          bestCost = cost;
          bestSplit = b;
        }
      }
      if (bestSplit < 0 && count <= kLeafSize) return result;
      if (bestSplit >= 0) {
        auto* split = std::partition(items_.data() + begin, items_.data() + end,
                                     [&](std::uint32_t item) { return binOf(item) <= bestSplit; });
        mid = static_cast<std::uint32_t>(split - items_.data());
      }
    } else if (count <= kLeafSize) {
      return result;
    }
    if (mid == begin || mid == end) {
      // SAH found nothing useful (equal centroids, or no good plane) but there
      // are too many items for a leaf: split at the median.
      mid = begin + count / 2;
      std::nth_element(items_.data() + begin, items_.data() + mid, items_.data() + end,
                       [&](std::uint32_t l, std::uint32_t r) { return centroids_[l][axis] < centroids_[r][axis]; });
    }
    result.leaf = false;
    result.mid = mid;
    return result;
  }

  std::vector<std::uint32_t>& items_;  // each subtree partitions its own range only
  const std::vector<Bounds<T>>& boxes_;
  std::vector<Vec3<T>> centroids_;
};

}  // namespace

template <typename T>
Bvh<T>::Bvh(const std::vector<Bounds<T>>& boxes, unsigned threads) {
  if (boxes.empty()) return;
  for (const Bounds<T>& b : boxes)
    if (b.empty() || !b.isFinite())
      throw Error(ErrorKind::Internal, "BVH built over an empty or infinite box; the union must keep those apart");
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0u);
  Subtree<T> tree = BvhBuilder<T>(items_, boxes).build(0, static_cast<std::uint32_t>(boxes.size()), 1, threads);
  nodes_ = std::move(tree.nodes);
  depth_ = tree.depth;
}

#define LATTICE_INSTANTIATE(T) template class Bvh<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
