// Collapsing the binary SAH tree into 4- or 8-wide nodes with float boxes
// rounded outwards, and the run-time choice of the width (method:
// render/accel/wide_bvh.hpp).
#include "render/accel/wide_bvh.hpp"

#include <algorithm>
#include <atomic>

namespace lattice {

namespace {

std::atomic<WideForm> autoForm{WideForm::Auto};

template <typename T>
double halfArea(const Bounds<T>& b) {
  Vec3<double> e = Vec3<double>(b.hi) - Vec3<double>(b.lo);
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The number of items under each binary node (a subtree's items are one run
// of items(), starting at its leftmost leaf's first).
template <typename T>
std::vector<std::uint32_t> subtreeSizes(const Bvh<T>& binary) {
  const auto& bn = binary.nodes();
  std::vector<std::uint32_t> size(bn.size(), 0);
  for (std::size_t n = bn.size(); n-- > 0;)  // children come after their parent
    size[n] = bn[n].count > 0 ? bn[n].count : size[n + 1] + size[bn[n].first];
  return size;
}

}  // namespace

void setWideForm(WideForm form) { autoForm.store(form, std::memory_order_relaxed); }

bool eightWideRuns() {
#if LATTICE_WIDE8
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

WideForm resolveWideForm(WideForm form) {
  if (form == WideForm::Auto) form = autoForm.load(std::memory_order_relaxed);
  if (form == WideForm::Four) return WideForm::Four;
  return eightWideRuns() ? WideForm::Eight : WideForm::Four;  // Auto and Eight
}

template <typename T>
WideBvh<T>::WideBvh(const std::vector<Bounds<T>>& boxes, WideForm form, LeafItems leaves, unsigned threads) {
  if (boxes.empty()) return;
  const Bvh<T> binary(boxes, threads);
  items_.assign(binary.items().begin(), binary.items().end());
  binaryDepth_ = binary.depth();
#if LATTICE_WIDE8
  if (resolveWideForm(form) == WideForm::Eight) {
    nodes8_.reserve(binary.nodes().size() / 4 + 1);
    collapse(nodes8_, binary, leaves == LeafItems::Culled ? subtreeSizes(binary) : std::vector<std::uint32_t>{}, 0, 1);
    return;
  }
#else
  (void)form, (void)leaves;
#endif
  nodes_.reserve(binary.nodes().size() / 2 + 1);
  collapse(nodes_, binary, {}, 0, 1);
}

template <typename T>
template <typename NodeT>
std::uint32_t WideBvh<T>::collapse(std::vector<NodeT>& out, const Bvh<T>& binary,
                                   const std::vector<std::uint32_t>& sizes, std::uint32_t index, int depth) {
  constexpr int kLanes = NodeT::kLanes;
  depth_ = std::max(depth_, depth);
  const auto& bn = binary.nodes();
  // A subtree of at most kLaneItems items is one leaf lane (sizes given).
  const auto isLeaf = [&](std::uint32_t k) { return bn[k].count > 0 || (!sizes.empty() && sizes[k] <= kLaneItems); };
  const auto firstItem = [&](std::uint32_t k) {
    while (bn[k].count == 0) k = k + 1;  // the leftmost leaf
    return bn[k].first;
  };
  // The binary children this wide node takes; a binary leaf at the root is
  // its one lane.
  std::uint32_t kids[kLanes];
  int n = 0;
  if (bn[index].count > 0) {
    kids[n++] = index;
  } else {
    kids[n++] = index + 1;
    kids[n++] = bn[index].first;
  }
  while (n < kLanes) {
    int open = -1;
    for (int k = 0; k < n; ++k)
      if (!isLeaf(kids[k]) && (open < 0 || halfArea(bn[kids[k]].box) > halfArea(bn[kids[open]].box))) open = k;
    if (open < 0) break;
    const std::uint32_t opened = kids[open];
    kids[open] = opened + 1;  // keeps left before right, the binary tree's order
    for (int k = n; k > open + 1; --k) kids[k] = kids[k - 1];
    kids[open + 1] = bn[opened].first;
    ++n;
  }
  const std::uint32_t self = static_cast<std::uint32_t>(out.size());
  out.push_back({});
  for (int lane = 0; lane < kLanes; ++lane)
    for (int a = 0; a < 3; ++a) {
      // Unused lanes hold an empty box; `used` masks them out anyway.
      out[self].lanes.box[0][a][lane] = 1.0f;
      out[self].lanes.box[1][a][lane] = -1.0f;
    }
  for (int lane = 0; lane < n; ++lane) {
    const auto& child = bn[kids[lane]];
    for (int a = 0; a < 3; ++a) {
      out[self].lanes.box[0][a][lane] = floatBelow(child.box.lo[a]);
      out[self].lanes.box[1][a][lane] = floatAbove(child.box.hi[a]);
    }
    out[self].used |= 1u << lane;
    if (isLeaf(kids[lane])) {
      out[self].ref[lane] = firstItem(kids[lane]);
      out[self].count[lane] =
          static_cast<std::remove_reference_t<decltype(out[self].count[lane])>>(child.count > 0 ? child.count : sizes[kids[lane]]);
    } else {
      const std::uint32_t wide = collapse(out, binary, sizes, kids[lane], depth + 1);  // may reallocate out
      out[self].ref[lane] = wide;
      out[self].count[lane] = 0;
    }
  }
  return self;
}

template class WideBvh<float>;
template class WideBvh<double>;

}  // namespace lattice
