#pragma once
// The rasterizer's hits, held as the lists it made them in (one per entry
// point, each sized exactly) and read as one sequence.
//
// Why not one flat vector: joining the lists into one needs the lists and
// the joined copy at once, twice the hits' 40 bytes each, and that moment
// was the whole process's peak under `--memory-budget` (the fuzzy sphere's
// hair: 0.88 MB of hits, 2.1 MB of heap while joining; docs/memory.md). The
// tables read hits in order (range-for) or by number (operator[], a binary
// search over the lists' starts); both see the order the lists were made in.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

#include "lht/grid/lattice_box.hpp"
#include "foundation/vec.hpp"

namespace lattice::lht {

// One (p_i, p_o) pair that hits the object.
struct RasterHit {
  LatticePoint in, out;
  double s = 0.0;    // hit = in + (out - in) s
  Vec3d normal{};    // unit, lattice coordinates (= object directions: the map is a uniform scale)
};

class RasterHits {
 public:
  RasterHits() = default;
  // One list (tests and tools that make hits by hand).
  RasterHits(std::vector<RasterHit> hits) { append(std::move(hits)); }  // NOLINT: implicit on purpose
  // Lists in order; empty ones are dropped.
  explicit RasterHits(std::vector<std::vector<RasterHit>> lists) {
    for (auto& list : lists) append(std::move(list));
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // Heap bytes the hits take (what a memory plan counts).
  std::uint64_t bytes() const {
    std::uint64_t b = lists_.capacity() * sizeof(std::vector<RasterHit>) + starts_.capacity() * sizeof(std::size_t);
    for (const auto& list : lists_) b += list.capacity() * sizeof(RasterHit);
    return b;
  }
  const RasterHit& operator[](std::size_t n) const {
    const std::size_t list = static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), n) -
                                                      starts_.begin()) - 1;
    return lists_[list][n - starts_[list]];
  }

  class const_iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = RasterHit;
    using difference_type = std::ptrdiff_t;
    using pointer = const RasterHit*;
    using reference = const RasterHit&;
    const_iterator() = default;
    const_iterator(const std::vector<std::vector<RasterHit>>* lists, std::size_t list, std::size_t at)
        : lists_(lists), list_(list), at_(at) {}
    reference operator*() const { return (*lists_)[list_][at_]; }
    pointer operator->() const { return &**this; }
    const_iterator& operator++() {
      if (++at_ == (*lists_)[list_].size()) ++list_, at_ = 0;  // lists are never empty
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator old = *this;
      ++*this;
      return old;
    }
    friend bool operator==(const const_iterator& a, const const_iterator& b) {
      return a.list_ == b.list_ && a.at_ == b.at_;
    }

   private:
    const std::vector<std::vector<RasterHit>>* lists_ = nullptr;
    std::size_t list_ = 0, at_ = 0;
  };
  const_iterator begin() const { return {&lists_, 0, 0}; }
  const_iterator end() const { return {&lists_, lists_.size(), 0}; }

  // The hits as one vector (tests and tools; the tables never need it).
  std::vector<RasterHit> flat() const { return {begin(), end()}; }

 private:
  void append(std::vector<RasterHit> list) {
    if (list.empty()) return;
    starts_.push_back(size_);
    size_ += list.size();
    lists_.push_back(std::move(list));
  }

  std::vector<std::vector<RasterHit>> lists_;
  std::vector<std::size_t> starts_;  // the number of each list's first hit
  std::size_t size_ = 0;
};

}  // namespace lattice::lht
