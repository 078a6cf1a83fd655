// BVH construction: binned surface area heuristic. The expected cost of a
// split is proportional to sum over sides of (surface area x item count),
// since the chance that a ray through the parent also hits a child box is
// about the ratio of their areas.
#include "render/accel/bvh.hpp"

#include <algorithm>
#include <numeric>

#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

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

}  // namespace

template <typename T>
Bvh<T>::Bvh(const std::vector<Bounds<T>>& boxes) {
  if (boxes.empty()) return;
  for (const Bounds<T>& b : boxes)
    if (b.empty() || !b.isFinite())
      throw Error(ErrorKind::Internal, "BVH built over an empty or infinite box; the union must keep those apart");
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0u);
  // Points, not boxes of zero size: half the bytes while the tree is built,
  // the build's peak on a 5000-instance scatter (docs/memory.md).
  std::vector<Vec3<T>> centroids(boxes.size());
  for (std::size_t n = 0; n < boxes.size(); ++n) centroids[n] = boxes[n].center();
  nodes_.reserve(2 * boxes.size());
  build(centroids, boxes, 0, static_cast<std::uint32_t>(boxes.size()), 1);
}

template <typename T>
std::uint32_t Bvh<T>::build(const std::vector<Vec3<T>>& centroids, const std::vector<Bounds<T>>& boxes,
                            std::uint32_t begin, std::uint32_t end, int depth) {
  depth_ = std::max(depth_, depth);
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Bounds<T> box, cbox;
  for (std::uint32_t n = begin; n < end; ++n) {
    box.extend(boxes[items_[n]]);
    cbox.extend(centroids[items_[n]]);
  }
  nodes_[index].box = box;
  const std::uint32_t count = end - begin;
  auto makeLeaf = [&] {
    nodes_[index].first = begin;
    nodes_[index].count = count;
    return index;
  };
  if (count <= 1 || depth >= kMaxDepth - 4) return makeLeaf();

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
      int b = static_cast<int>((double(centroids[item][axis]) - lo) * scale);
      return std::clamp(b, 0, kBins - 1);
    };
    for (std::uint32_t n = begin; n < end; ++n) {
      Bin& bin = bins[binOf(items_[n])];
      bin.box.extend(boxes[items_[n]]);
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
    if (bestSplit < 0 && count <= kLeafSize) return makeLeaf();
    if (bestSplit >= 0) {
      auto* split = std::partition(items_.data() + begin, items_.data() + end,
                                   [&](std::uint32_t item) { return binOf(item) <= bestSplit; });
      mid = static_cast<std::uint32_t>(split - items_.data());
    }
  } else if (count <= kLeafSize) {
    return makeLeaf();
  }
  if (mid == begin || mid == end) {
    // SAH found nothing useful (equal centroids, or no good plane) but there
    // are too many items for a leaf: split at the median.
    mid = begin + count / 2;
    std::nth_element(items_.data() + begin, items_.data() + mid, items_.data() + end,
                     [&](std::uint32_t l, std::uint32_t r) { return centroids[l][axis] < centroids[r][axis]; });
  }
  build(centroids, boxes, begin, mid, depth + 1);
  std::uint32_t right = build(centroids, boxes, mid, end, depth + 1);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

#define LATTICE_INSTANTIATE(T) template class Bvh<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
