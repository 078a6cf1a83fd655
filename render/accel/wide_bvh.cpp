// Collapsing the binary SAH tree into 4-wide nodes with float boxes rounded
// outwards (method: render/accel/wide_bvh.hpp).
#include "render/accel/wide_bvh.hpp"

#include <algorithm>

namespace lattice {

namespace {

template <typename T>
double halfArea(const Bounds<T>& b) {
  Vec3<double> e = Vec3<double>(b.hi) - Vec3<double>(b.lo);
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

}  // namespace

template <typename T>
WideBvh<T>::WideBvh(const std::vector<Bounds<T>>& boxes, unsigned threads) {
  if (boxes.empty()) return;
  const Bvh<T> binary(boxes, threads);
  items_.assign(binary.items().begin(), binary.items().end());
  binaryDepth_ = binary.depth();
  nodes_.reserve(binary.nodes().size() / 2 + 1);
  collapse(binary, 0, 1);
}

template <typename T>
std::uint32_t WideBvh<T>::collapse(const Bvh<T>& binary, std::uint32_t index, int depth) {
  depth_ = std::max(depth_, depth);
  const auto& bn = binary.nodes();
  // The binary children this wide node takes; a binary leaf at the root is
  // its one lane.
  std::uint32_t kids[4];
  int n = 0;
  if (bn[index].count > 0) {
    kids[n++] = index;
  } else {
    kids[n++] = index + 1;
    kids[n++] = bn[index].first;
  }
  while (n < 4) {
    int open = -1;
    for (int k = 0; k < n; ++k)
      if (bn[kids[k]].count == 0 && (open < 0 || halfArea(bn[kids[k]].box) > halfArea(bn[kids[open]].box))) open = k;
    if (open < 0) break;
    const std::uint32_t opened = kids[open];
    kids[open] = opened + 1;  // keeps left before right, the binary tree's order
    for (int k = n; k > open + 1; --k) kids[k] = kids[k - 1];
    kids[open + 1] = bn[opened].first;
    ++n;
  }
  const std::uint32_t self = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  for (int lane = 0; lane < 4; ++lane)
    for (int a = 0; a < 3; ++a) {
      // Unused lanes hold an empty box; `used` masks them out anyway.
      nodes_[self].lanes.box[0][a][lane] = 1.0f;
      nodes_[self].lanes.box[1][a][lane] = -1.0f;
    }
  for (int lane = 0; lane < n; ++lane) {
    const auto& child = bn[kids[lane]];
    for (int a = 0; a < 3; ++a) {
      nodes_[self].lanes.box[0][a][lane] = floatBelow(child.box.lo[a]);
      nodes_[self].lanes.box[1][a][lane] = floatAbove(child.box.hi[a]);
    }
    nodes_[self].used |= 1u << lane;
    if (child.count > 0) {
      nodes_[self].ref[lane] = child.first;
      nodes_[self].count[lane] = child.count;
    } else {
      const std::uint32_t wide = collapse(binary, kids[lane], depth + 1);  // may reallocate nodes_
      nodes_[self].ref[lane] = wide;
      nodes_[self].count[lane] = 0;
    }
  }
  return self;
}

template class WideBvh<float>;
template class WideBvh<double>;

}  // namespace lattice
