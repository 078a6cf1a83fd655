#pragma once
// A count for statistics, bumped by any number of threads: rays traced,
// table look-ups and hits, pairs traced on demand, solver fallbacks.
//
// Method: one relaxed atomic. A statistic orders nothing: it is read once
// the threads that bump it have been joined (which orders their writes
// before the read) or, read while they run, as a figure that may be a few
// counts behind.
#include <atomic>
#include <cstdint>

namespace lattice {

class Counter {
 public:
  void add(std::uint64_t n = 1) noexcept { value_.fetch_add(n, std::memory_order_relaxed); }
  std::uint64_t value() const noexcept { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<std::uint64_t> value_{0};
};

}  // namespace lattice
