#pragma once
// The lattice hash table, LHT (thesis sec. 2.3): the rasterized hits keyed by
// (p_i, p_o), in the thesis's compact 14-byte entry, with open hashing into
// an overflow area.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lht/lattice_box.hpp"
#include "lht/rasterize.hpp"

namespace lattice::lht {

// Thesis sec. 2.3: (p_i, p_o) in 6 bytes, s * 255 in one byte, the unit
// normal * 127 in three signed bytes and a 4-byte overflow index. Every field
// is a byte array, so the struct has no padding on any ABI and its bytes are
// the file format (the overflow index is little-endian).
struct LhtEntry {
  std::uint8_t key[6];
  std::uint8_t s;
  std::int8_t normal[3];
  std::uint8_t next[4];
};
static_assert(sizeof(LhtEntry) == 14, "the LHT entry must be the thesis's 14 bytes");

inline constexpr std::uint32_t kNoNext = 0xFFFFFFFFu;

// A decoded entry: the hit as the renderer uses it.
struct LhtHit {
  double s = 0.0;
  Vec3d normal{};  // unit, lattice coordinates
};

// Quantization (thesis: "a small but acceptable truncation error"); we round
// to nearest, so s is within 1/510 and each normal component within 1/254.
std::uint8_t quantizeS(double s);
std::int8_t quantizeNormalComponent(double n);
LhtEntry encodeEntry(const RasterHit& hit);
LhtHit decodeEntry(const LhtEntry& entry);

struct ChainStats {
  std::uint64_t usedBuckets = 0;
  std::uint64_t longestChain = 0;
  std::vector<std::uint64_t> chainLengthHistogram;  // [k] = buckets whose chain has k entries
};

class LatticeHashTable {
 public:
  // Entries per bucket: higher packs tighter (fewer empty primary slots)
  // but walks longer chains. 2 gives ~15 bytes/entry with chains averaging 2.
  static constexpr double kDefaultLoadFactor = 2.0;

  LatticeHashTable() = default;
  // Builds from rasterized hits (distinct keys).
  explicit LatticeHashTable(const std::vector<RasterHit>& hits, double loadFactor = kDefaultLoadFactor);
  // Adopts slots read from a file; throws lattice::Error(Input) if the chains
  // are not well formed (an index out of range, a cycle, a misplaced key).
  LatticeHashTable(std::vector<LhtEntry> slots, std::uint64_t bucketCount, std::uint64_t entryCount);

  std::optional<LhtHit> find(const LatticePoint& in, const LatticePoint& out) const;
  // The stored entry itself (null if absent): fixed-point rendering decodes
  // its bytes in integers instead of through LhtHit's doubles.
  const LhtEntry* findEntry(const LatticePoint& in, const LatticePoint& out) const;

  std::uint64_t entryCount() const { return entries_; }
  std::uint64_t bucketCount() const { return buckets_; }
  std::uint64_t overflowCount() const { return slots_.size() - buckets_; }
  std::uint64_t bytes() const { return slots_.size() * sizeof(LhtEntry); }
  double loadFactor() const { return buckets_ ? double(entries_) / double(buckets_) : 0.0; }
  double bytesPerEntry() const { return entries_ ? double(bytes()) / double(entries_) : 0.0; }
  ChainStats chainStats() const;
  const std::vector<LhtEntry>& slots() const { return slots_; }

  static std::uint64_t bucketOf(const std::uint8_t key[6], std::uint64_t bucketCount);

 private:
  std::vector<LhtEntry> slots_;  // [0, buckets_) primary, the rest the overflow area
  std::uint64_t buckets_ = 0;
  std::uint64_t entries_ = 0;
};

}  // namespace lattice::lht
