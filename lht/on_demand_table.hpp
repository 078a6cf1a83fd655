#pragma once
// The LHT built on demand (thesis sec. 5.2.2): the table starts empty; a
// look-up of a pair it does not hold traces that pair against the object
// (lht/rasterize.hpp's PairTracer, so the answer is the precomputed table's
// to the byte) and stores the hit or the miss.
//
// Method and tunables:
// * Storage: kShards shards, each a mutex and a hash map from the ordered
//   pair number (lht/boundary_index.hpp) to the answer (hit flag and the
//   entry precision's payload). Answers are never erased, so a payload's
//   address stays valid without the lock; two threads asking a new pair at
//   once may both trace it, and the first store wins (the same bytes).
// * Bound: `capacityBytes` (`--lht-cache SIZE`) over kStoredBytes a stored
//   answer (the map node with its key and payload, measured for libstdc++'s
//   unordered_map: 40 bytes, plus the bucket array, rounded up to 48). When
//   it is reached the table refuses new stores and traces every further
//   unknown pair again (the pictures stay identical; only time is lost).
//   Refusing rather than evicting keeps the table lock-free on the hit path
//   and keeps every returned address valid.
// * Counters (relaxed atomics): hits and misses stored, pairs traced, stores
//   refused; what `render --lht-stats` reports as "entries built".
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "lht/boundary_index.hpp"
#include "lht/entry_codec.hpp"
#include "lht/rasterize.hpp"

namespace lattice::lht {

struct OnDemandCounts {
  std::uint64_t hitsStored = 0, missesStored = 0, traced = 0, refused = 0, capacityBytes = 0;
};

class OnDemandTable {
 public:
  static constexpr std::size_t kShards = 64;
  static constexpr std::uint64_t kStoredBytes = 48;

  // `object` must outlive the table (it is kept with it: LhtFile::onDemand).
  OnDemandTable(const LatticeBox& box, std::shared_ptr<const Primitive<double>> object, LhtPrecision precision,
                std::uint64_t capacityBytes);

  // The pair's payload, traced now if it was never asked; null for a miss.
  const std::uint8_t* findPayload(const LatticePoint& in, const LatticePoint& out) const;

  LhtPrecision precision() const { return precision_; }
  OnDemandCounts counts() const;
  std::uint64_t entryCount() const { return hitsStored_.load(std::memory_order_relaxed); }
  std::uint64_t bytes() const { return (hitsStored_ + missesStored_) * kStoredBytes; }

 private:
  struct Answer {
    bool hit = false;
    std::array<std::uint8_t, 6> payload{};
  };
  struct Shard {
    std::mutex mutex;
    std::unordered_map<std::uint64_t, Answer> answers;
  };

  LatticeBox box_;
  std::shared_ptr<const Primitive<double>> object_;
  PairTracer tracer_;
  BoundaryIndex index_;
  LhtPrecision precision_;
  std::uint64_t capacity_;  // answers
  mutable std::array<Shard, kShards> shards_;
  mutable std::atomic<std::uint64_t> hitsStored_{0}, missesStored_{0}, traced_{0}, refused_{0};
};

}  // namespace lattice::lht
