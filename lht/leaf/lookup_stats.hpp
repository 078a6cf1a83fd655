#pragma once
// How much of a lattice's table a render touches (thesis sec. 5.2.1, 5.2.2:
// "many of the N_iz entries are never referenced"): `lattice render
// --lht-stats`.
//
// Method and tunables:
// * Off unless asked: a leaf holds a null LookupStats pointer and tests it
//   once per look-up (a branch that always goes the same way).
// * On: three relaxed atomic counters (look-ups, hits, off-surface points)
//   and an atomic bitmap over the ordered pairs of boundary points
//   (lht/grid/boundary_index.hpp; P^2 bits, 14.5 MB for the hair at f_lat 4), so
//   many render threads count exactly; the distinct pairs asked are its set
//   bits, read once the render is over.
// * kMaxPairBits = 2^33 (1 GiB): above it the distinct pairs are not
//   counted (reported as such); the counters still are.
// * Entries referenced: each distinct pair asked that the table holds. As a
//   share of N_iz they are weighted by eq. 1.3's multiplicity (a pair
//   between edge or corner points counts once per pair of faces, as the
//   rasterizer counts N_iz), and also given as a share of the entries.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "foundation/counter.hpp"
#include "foundation/threads.hpp"
#include "lht/grid/boundary_index.hpp"
#include "lht/file/lht_file.hpp"

namespace lattice::lht {

struct LookupSummary {
  std::string lattice;
  std::uint64_t lookups = 0, hits = 0, misses = 0;
  bool distinctCounted = true;  // false: the pair space was above kMaxPairBits
  std::uint64_t distinctPairs = 0;         // distinct (p_i, p_o) asked
  std::uint64_t pairSpace = 0;             // P (P - 1): ordered pairs of distinct boundary points
  std::uint64_t entries = 0;               // distinct hitting pairs stored
  std::uint64_t entriesReferenced = 0;     // of them, asked at least once
  std::uint64_t nIz = 0;                   // N_iz (eq. 1.3 multiplicity)
  std::uint64_t nIzReferenced = 0;         // referenced entries weighted the same way
  std::uint64_t offSurface = 0;            // look-ups whose points were not on the box's surface
  double oversample = 1.0;
  std::optional<OnDemandCounts> onDemand;  // the on-demand form: what it built
};

class LookupStats {
 public:
  static constexpr std::uint64_t kMaxPairBits = std::uint64_t(1) << 33;

  LookupStats(std::string lattice, std::shared_ptr<const LhtFile> lht);

  void record(const LatticePoint& in, const LatticePoint& out, bool hit) {
    lookups_.add();
    if (hit) hits_.add();
    const std::uint64_t i = index_.indexOf(in), o = index_.indexOf(out);
    if (i == BoundaryIndex::kNotOnBoundary || o == BoundaryIndex::kNotOnBoundary) {
      offSurface_.add();
      return;
    }
    if (asked_.empty()) return;
    const std::uint64_t bit = i * index_.count() + o;
    asked_[bit / 64].fetch_or(std::uint64_t(1) << (bit % 64), std::memory_order_relaxed);
  }

  // Read once the render's threads are done.
  LookupSummary summary() const;

 private:
  std::string lattice_;
  std::shared_ptr<const LhtFile> lht_;
  BoundaryIndex index_;
  Counter lookups_, hits_, offSurface_;
  std::vector<std::atomic<std::uint64_t>> asked_;  // one bit per ordered pair; empty above kMaxPairBits
};

// The stats of every lattice of a render, in the order their tables were made.
class LookupStatsBook {
 public:
  LookupStats* add(std::string lattice, std::shared_ptr<const LhtFile> lht);
  std::vector<LookupSummary> summaries() const;

 private:
  mutable Mutex mutex_;
  std::vector<std::unique_ptr<LookupStats>> stats_;
};

// The lines `render --lht-stats` prints for one lattice.
std::string describeLookups(const LookupSummary& s);

}  // namespace lattice::lht
