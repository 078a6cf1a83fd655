#pragma once
// The lattice hash table, LHT (thesis sec. 2.3): the rasterized hits keyed by
// (p_i, p_o), in compact fixed-size entries (lht/entry_codec.hpp; the
// thesis's 14 bytes by default, lht/lht_precision.hpp for the other forms),
// with open hashing into an overflow area. The hashing and chaining are the
// same for every precision: only the slot stride and the payload differ.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lht/entry_codec.hpp"
#include "lht/lattice_box.hpp"
#include "lht/lht_precision.hpp"
#include "lht/rasterize.hpp"

namespace lattice::lht {

struct ChainStats {
  std::uint64_t usedBuckets = 0;
  std::uint64_t longestChain = 0;
  std::vector<std::uint64_t> chainLengthHistogram;  // [k] = buckets whose chain has k entries
};

class LatticeHashTable {
 public:
  // Entries per bucket: higher packs tighter (fewer empty primary slots)
  // but walks longer chains. 2 gives ~1.07 slots per entry with chains averaging 2.
  static constexpr double kDefaultLoadFactor = 2.0;

  LatticeHashTable() = default;
  // Builds from rasterized hits (distinct keys), each stored at `precision`.
  explicit LatticeHashTable(const RasterHits& hits, LhtPrecision precision = LhtPrecision::Thesis,
                            double loadFactor = kDefaultLoadFactor);
  // Adopts slots read from a file (slotBytes.size() a multiple of
  // entryBytes(precision)); throws lattice::Error(Input) if the chains are
  // not well formed (an index out of range, a cycle, a misplaced key).
  LatticeHashTable(LhtPrecision precision, std::vector<std::uint8_t> slotBytes, std::uint64_t bucketCount,
                   std::uint64_t entryCount);

  // Reads slots that stay where they are (a baked table in the firmware's
  // flash, docs/firmware.md): no copy, checked like a file's; `slotBytes`
  // must outlive the table.
  static LatticeHashTable inPlace(LhtPrecision precision, std::span<const std::uint8_t> slotBytes,
                                  std::uint64_t bucketCount, std::uint64_t entryCount);

  std::optional<LhtHit> find(const LatticePoint& in, const LatticePoint& out) const;
  // The stored entry's bytes (entryBytes(precision()) of them; null if
  // absent): fixed-point rendering decodes them with decodeEntryIntegers()
  // instead of through LhtHit's doubles.
  const std::uint8_t* findEntry(const LatticePoint& in, const LatticePoint& out) const;
  // The entry's payload (payloadBytes(precision()) bytes after the key); null if absent.
  const std::uint8_t* findPayload(const LatticePoint& in, const LatticePoint& out) const {
    const std::uint8_t* e = findEntry(in, out);
    return e ? e + kEntryKeyBytes : nullptr;
  }

  LhtPrecision precision() const { return precision_; }
  std::size_t entryStride() const { return stride_; }
  std::uint64_t entryCount() const { return entries_; }
  std::uint64_t bucketCount() const { return buckets_; }
  std::uint64_t slotCount() const { return slotView().size() / stride_; }
  std::uint64_t overflowCount() const { return slotCount() - buckets_; }
  std::uint64_t bytes() const { return slotView().size(); }
  double loadFactor() const { return buckets_ ? double(entries_) / double(buckets_) : 0.0; }
  double bytesPerEntry() const { return entries_ ? double(bytes()) / double(entries_) : 0.0; }
  ChainStats chainStats() const;
  // Every slot, primary then overflow, entryStride() bytes each: the file's bytes.
  // (The owned copy; empty for a table read in place.)
  const std::vector<std::uint8_t>& slotBytes() const { return slots_; }
  // The slots wherever they are.
  std::span<const std::uint8_t> slotView() const { return inPlace_.data() ? inPlace_ : std::span<const std::uint8_t>(slots_); }

  static std::uint64_t bucketOf(const std::uint8_t key[6], std::uint64_t bucketCount);
  // The slots a table of these hits over bucketCount buckets will have.
  static std::uint64_t slotsFor(const RasterHits& hits, std::uint64_t bucketCount);
  // The bytes a table of `entries` hits is expected to take, before it is
  // built (a memory budget chooses the precision with it); within about 1 %
  // for tables of thousands of entries.
  static std::uint64_t expectedBytes(std::uint64_t entries, LhtPrecision precision,
                                     double loadFactor = kDefaultLoadFactor);

 private:
  const std::uint8_t* slot(std::uint64_t index) const { return slotView().data() + index * stride_; }
  std::uint8_t* slot(std::uint64_t index) { return slots_.data() + index * stride_; }
  std::uint32_t nextOf(std::uint64_t index) const;
  void setNext(std::uint64_t index, std::uint32_t next);
  bool isEmpty(std::uint64_t index) const;
  void checkChains() const;

  LhtPrecision precision_ = LhtPrecision::Thesis;
  std::size_t stride_ = entryBytes(LhtPrecision::Thesis);
  std::vector<std::uint8_t> slots_;  // slots [0, buckets_) primary, the rest the overflow area
  std::span<const std::uint8_t> inPlace_;  // instead of slots_, for a table read in place
  std::uint64_t buckets_ = 0;
  std::uint64_t entries_ = 0;
};

}  // namespace lattice::lht
