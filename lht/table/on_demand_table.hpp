#pragma once
// The LHT built on demand (thesis sec. 5.2.2): the table starts empty; a
// look-up of a pair it does not hold traces that pair against the object
// (lht/raster/rasterize.hpp's PairTracer, so the answer is the precomputed table's
// to the byte) and stores the hit or the miss.
//
// Method and tunables:
// * Storage: kShards shards, each a mutex and a hash map from the ordered
//   pair number (lht/grid/boundary_index.hpp) to the answer (hit flag and the
//   entry precision's payload). Answers are never erased, so a payload's
//   address stays valid without the lock; two threads asking a new pair at
//   once may both trace it, and the first store wins (the same bytes).
// * Misses: one bit per ordered pair (P^2 bits: 3.7 MB for the hair at
//   f_lat 4, 18 KB at f_lat 1), set with a relaxed atomic OR and read
//   without a lock: two thirds of a plate's look-ups miss, and the profile
//   before this bitmap had unordered_map::find at 29 % of a render. Pair
//   spaces above kMaxMissBits (2^30 bits, 128 MiB) keep their misses in the
//   maps instead.
// * Bound: `capacityBytes` (`--lht-cache SIZE`) over kStoredBytes a stored
//   map answer (the node with its key and payload, measured for libstdc++'s
//   unordered_map: 40 bytes, plus the bucket array, rounded up to 48); the
//   miss bitmap is apart from it. When it is reached the table refuses new
//   stores and traces every further unknown pair again (the pictures stay
//   identical; only time is lost). Refusing rather than evicting keeps every
//   returned address valid without reference counts.
// * Counters (relaxed atomics): hits and misses stored, pairs traced, stores
//   refused; what `render --lht-stats` reports as "entries built".
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "foundation/counter.hpp"
#include "foundation/threads.hpp"
#include "lht/grid/boundary_index.hpp"
#include "lht/table/entry_codec.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

struct OnDemandCounts {
  std::uint64_t hitsStored = 0, missesStored = 0, traced = 0, refused = 0, capacityBytes = 0;
  std::uint64_t mapAnswers = 0;       // answers in the maps (the bounded part)
  std::uint64_t missBitmapBytes = 0;  // the miss bitmap (apart from the bound)
};

class OnDemandTable {
 public:
  // Its entry in the form list (lht/table/table_forms.hpp): built while
  // rendering, never rasterized, never in a file.
  static constexpr std::string_view kFormName = "on-demand";
  static constexpr std::string_view kFormSummary = "on-demand (traced at the first look-up of each pair)";
  static constexpr bool kInFiles = false;

  static constexpr std::size_t kShards = 64;
  static constexpr std::uint64_t kStoredBytes = 48;
  static constexpr std::uint64_t kMaxMissBits = std::uint64_t(1) << 30;

  // `object` must outlive the table (it is kept with it: LhtFile::onDemand).
  OnDemandTable(const LatticeBox& box, std::shared_ptr<const Primitive<double>> object, LhtPrecision precision,
                std::uint64_t capacityBytes);

  // The pair's payload, traced now if it was never asked; null for a miss.
  const std::uint8_t* findPayload(const LatticePoint& in, const LatticePoint& out) const;

  LhtPrecision precision() const { return precision_; }
  OnDemandCounts counts() const;
  std::uint64_t entryCount() const { return hitsStored_.value(); }
  std::uint64_t bytes() const { return mapAnswers_.value() * kStoredBytes + missBits_.size() * 8; }

 private:
  struct Answer {
    bool hit = false;
    std::array<std::uint8_t, 6> payload{};
  };
  struct Shard {
    Mutex mutex;
    std::unordered_map<std::uint64_t, Answer> answers;
  };

  LatticeBox box_;
  std::shared_ptr<const Primitive<double>> object_;
  PairTracer tracer_;
  BoundaryIndex index_;
  LhtPrecision precision_;
  std::uint64_t capacity_;  // answers
  mutable std::array<Shard, kShards> shards_;
  mutable std::vector<std::atomic<std::uint64_t>> missBits_;  // empty above kMaxMissBits
  mutable Counter hitsStored_, missesStored_, mapAnswers_, traced_, refused_;
};

}  // namespace lattice::lht
