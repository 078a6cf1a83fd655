// The BVH's build (render/accel/bvh.cpp) against the plain form of its method,
// written out here: each node sweeps its items for its box and its centroids'
// bounds, bins them on the widest axis, sweeps all twelve bins from both
// ends, bins each item again to partition, and falls back to the median.
// The build gathers each side's extent per bin, reads each item's bin back
// and sweeps only the bins that hold items; it must give this tree node for
// node, item for item, or every picture over a BVH would move.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

#include "foundation/fixed.hpp"
#include "render/accel/bvh.hpp"
#include "scattered_boxes.hpp"

using namespace lattice;

namespace {

template <typename T>
double areaOf(const Bounds<T>& b) {
  if (b.empty()) return 0.0;
  const Vec3<double> e = Vec3<double>(b.hi) - Vec3<double>(b.lo);
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The method as docs and the original build state it, slow and plain.
template <typename T>
struct PlainBuild {
  const std::vector<Bounds<T>>& boxes;
  std::vector<Vec3<T>> centroids;
  std::vector<std::uint32_t> items;
  std::vector<typename Bvh<T>::Node> nodes;

  explicit PlainBuild(const std::vector<Bounds<T>>& b) : boxes(b), items(b.size()) {
    for (const Bounds<T>& box : boxes) centroids.push_back(box.center());
    std::iota(items.begin(), items.end(), 0u);
    node(0, static_cast<std::uint32_t>(items.size()), 1);
  }

  std::uint32_t node(std::uint32_t begin, std::uint32_t end, int depth) {
    const auto index = static_cast<std::uint32_t>(nodes.size());
    Bounds<T> box, cbox;
    for (std::uint32_t n = begin; n < end; ++n) {
      box.extend(boxes[items[n]]);
      cbox.extend(centroids[items[n]]);
    }
    nodes.push_back({box, begin, end - begin});
    const std::uint32_t count = end - begin;
    if (count <= 1 || depth >= Bvh<T>::kMaxDepth - 4) return index;
    int axis = 0;
    const Vec3<T> extent = cbox.hi - cbox.lo;
    if (extent.y > extent[axis]) axis = 1;
    if (extent.z > extent[axis]) axis = 2;
    constexpr int kBins = 12;
    std::uint32_t mid = begin;
    if (extent[axis] > T(0)) {
      const double lo = double(cbox.lo[axis]), scale = kBins / (double(cbox.hi[axis]) - lo);
      const auto binOf = [&](std::uint32_t item) {
        return std::clamp(static_cast<int>((double(centroids[item][axis]) - lo) * scale), 0, kBins - 1);
      };
      Bounds<T> binBox[kBins];
      std::uint32_t binCount[kBins] = {};
      for (std::uint32_t n = begin; n < end; ++n) {
        binBox[binOf(items[n])].extend(boxes[items[n]]);
        ++binCount[binOf(items[n])];
      }
      double rightCost[kBins];
      Bounds<T> acc;
      std::uint32_t accCount = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.extend(binBox[b]);
        accCount += binCount[b];
        rightCost[b] = areaOf(acc) * accCount;
      }
      double bestCost = areaOf(box) * count;
      int bestSplit = -1;
      acc = Bounds<T>();
      accCount = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.extend(binBox[b]);
        accCount += binCount[b];
        const double cost = areaOf(box) + areaOf(acc) * accCount + rightCost[b + 1];
        if (cost < bestCost) {
          bestCost = cost;
          bestSplit = b;
        }
      }
      if (bestSplit < 0 && count <= 4) return index;
      if (bestSplit >= 0)
        mid = static_cast<std::uint32_t>(
            std::partition(items.data() + begin, items.data() + end,
                           [&](std::uint32_t item) { return binOf(item) <= bestSplit; }) -
            items.data());
    } else if (count <= 4) {
      return index;
    }
    if (mid == begin || mid == end) {
      mid = begin + count / 2;
      std::nth_element(items.data() + begin, items.data() + mid, items.data() + end,
                       [&](std::uint32_t l, std::uint32_t r) { return centroids[l][axis] < centroids[r][axis]; });
    }
    node(begin, mid, depth + 1);
    const std::uint32_t right = node(mid, end, depth + 1);
    nodes[index].first = right;
    nodes[index].count = 0;
    return index;
  }
};

// scatteredBoxes, with every seventh box moved far out of its cluster (empty
// bins between) and every eleventh made flat (zero areas).
template <typename T>
std::vector<Bounds<T>> mixedBoxes(int n, unsigned seed) {
  std::vector<Bounds<T>> boxes = testing::scatteredBoxes<T>(n, seed);
  for (std::size_t i = 0; i < boxes.size(); i += 7) {
    const Vec3d away = (Vec3d(boxes[i].lo) - Vec3d(boxes[(i + 3) % boxes.size()].lo)) * 4.0;
    boxes[i] = {Vec3<T>(Vec3d(boxes[i].lo) + away), Vec3<T>(Vec3d(boxes[i].hi) + away)};
  }
  for (std::size_t i = 0; i < boxes.size(); i += 11) boxes[i].hi.y = boxes[i].lo.y;
  return boxes;
}

}  // namespace

TEMPLATE_TEST_CASE("BVH build: the plain method's tree, node for node", "[bvh]", float, double, Fixed32) {
  using T = TestType;
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<Bounds<T>> boxes = mixedBoxes<T>(seed == 3 ? 40 : 4000, seed);
    const PlainBuild<T> plain(boxes);
    for (unsigned threads : {1u, 2u}) {
      const Bvh<T> built(boxes, threads);
      REQUIRE(built.nodes().size() == plain.nodes.size());
      int differ = 0;
      for (std::size_t n = 0; n < plain.nodes.size(); ++n) {
        const auto &a = plain.nodes[n], &b = built.nodes()[n];
        if (a.first != b.first || a.count != b.count || a.box.lo != b.box.lo || a.box.hi != b.box.hi) ++differ;
      }
      CHECK(differ == 0);
      CHECK(std::equal(plain.items.begin(), plain.items.end(), built.items().begin(), built.items().end()));
    }
  }
}
