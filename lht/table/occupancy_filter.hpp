#pragma once
// The occupancy bitmap in front of a lattice's hash table
// (lht/table/hash_table.hpp): one bit per bucket of keys, set when a held key
// falls in it, so a look-up whose bit is clear is a miss without a probe.
// On the hair plates three look-ups in four miss (docs/benchmarks.md), and
// the bitmap is a tenth of the table's bytes, so it stays in cache where the
// slots do not.
//
// Method and tunables:
// * Bucket = the top log2(bits) bits of key * kMultiplier, an odd constant
//   other than the table's home hash (Fibonacci hashing's 2^64/phi), so the
//   keys one run of slots holds are spread over the bitmap rather than
//   sharing its bits.
// * Sized from the table: bits = the power of two at least kBitsPerEntry
//   times the entries (8 to 16 bits an entry, 1 to 2 bytes against the
//   table's 14.3); a clear bit is then expected for 1 - n/m of the absent
//   keys' buckets, about e^(-1/8) to e^(-1/16), 88 to 94 %, on uniform hashing
//   (Bloom, "Space/time trade-offs in hash coding with allowable errors",
//   CACM 13(7), 1970, with one hash function).
// * It only answers "absent" or "maybe": a set bit still probes the table,
//   so which entry a look-up finds is unchanged.
// * An empty filter (no bits) answers "maybe" to every key: a table read in
//   place from the firmware's flash keeps its RAM and has none.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace lattice::lht {

class OccupancyFilter {
 public:
  static constexpr std::uint64_t kBitsPerEntry = 8;
  static constexpr std::uint64_t kMinBits = 64;
  static constexpr std::uint64_t kMultiplier = 0xD6E8FEB86659FD93ull;

  OccupancyFilter() = default;
  // Room for `entries` keys, every bit clear.
  explicit OccupancyFilter(std::uint64_t entries)
      : shift_(64 - std::countr_zero(bitsFor(entries))), words_(static_cast<std::size_t>(bitsFor(entries) / 64), 0) {}

  // The bits a filter for `entries` keys has, and its bytes (the memory plan counts them).
  static std::uint64_t bitsFor(std::uint64_t entries) {
    return std::bit_ceil(std::max(kMinBits, entries * kBitsPerEntry));
  }
  static std::uint64_t bytesFor(std::uint64_t entries) { return bitsFor(entries) / 8; }

  void add(std::uint64_t key) {
    const std::uint64_t b = bucket(key);
    words_[static_cast<std::size_t>(b / 64)] |= std::uint64_t(1) << (b % 64);
  }
  // False only when no key added falls in key's bucket.
  bool mayHold(std::uint64_t key) const {
    if (words_.empty()) return true;
    const std::uint64_t b = bucket(key);
    return (words_[static_cast<std::size_t>(b / 64)] >> (b % 64)) & 1u;
  }
  bool empty() const { return words_.empty(); }
  std::uint64_t bits() const { return words_.size() * 64; }
  std::uint64_t bytes() const { return words_.size() * sizeof(std::uint64_t); }

 private:
  std::uint64_t bucket(std::uint64_t key) const { return (key * kMultiplier) >> shift_; }

  int shift_ = 64;
  std::vector<std::uint64_t> words_;
};

}  // namespace lattice::lht
