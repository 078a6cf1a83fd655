#pragma once
// The lattice hash table, LHT (thesis sec. 2.3): the rasterized hits keyed by
// (p_i, p_o), in compact fixed-size slots (lht/table/entry_codec.hpp: the key and
// the payload, the thesis's 10 of its 14 bytes by default,
// lht/table/lht_precision.hpp for the other forms).
//
// Method and tunables:
// * Open addressing with linear probing over one array of slots
//   (the thesis chained into an overflow area). A
//   look-up reads consecutive slots from the key's home until it meets the
//   key, a smaller one or an empty slot (below), so a miss (three in four look-ups on the hair
//   plates) costs one or two cache lines and no pointer chasing, and a slot
//   needs no overflow index (4 bytes saved per slot).
// * The key's six bytes are compared as one integer; an empty slot has the
//   all-zero key, (0,0,0)->(0,0,0), a point and never a hit.
// * Ordered hashing (Amble and Knuth, "Ordered hash tables", The Computer
//   Journal 17(2), 1974): along every probe run the keys met before a key
//   are larger than it, so a look-up stops at the first key not larger
//   than its own: a miss costs about what a hit does instead of walking the
//   run to its empty slot, and one comparison ends both. Insertion keeps
//   the order by carrying the smaller key on. The layout is then the same
//   whatever order the keys came in (a table rasterized with any number of
//   threads).
// * Home = h * capacity / 2^32, h the top 32 bits of key * 2^64/phi
//   (Fibonacci hashing: neighbouring lattice points, keys differing in one
//   low byte, land far apart). Two multiplies and shifts, no division, and
//   any capacity: a power-of-two capacity (a mask instead of the second
//   multiply) would leave the load anywhere in (kMaxLoad/2, kMaxLoad], up
//   to twice the bytes per entry (measured: a sphere's 1,562 entries in
//   4,096 slots, 26.2 bytes each instead of 14.3); 32-bit halves because
//   the Cortex-M3 firmware has no 128-bit product.
// * kMaxLoad = 0.7: the capacity is ceil(entries / 0.7), 14.3 bytes per
//   thesis entry (the chained layout took about 15.0). Linear probing's
//   expected hit length for random keys is (1 + 1/(1-a))/2 slots (Knuth,
//   TAOCP vol. 3, sec. 6.4): 2.2 slots, 22 bytes, at 0.7, and ordering
//   brings a miss to about the same (unordered: (1 + 1/(1-a)^2)/2, 6.1).
// * The same layout in memory, in a version-4 .lht file and in the
//   firmware's flash (read in place, docs/firmware.md).
// * An occupancy bitmap in front of the slots (lht/table/occupancy_filter.hpp,
//   built with the table, never stored in a file): a miss whose bit is clear
//   reads no slot. A table read in place has none (the firmware's RAM).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <span>
#include <vector>

#include "lht/table/entry_codec.hpp"
#include "lht/grid/lattice_box.hpp"
#include "lht/table/lht_precision.hpp"
#include "lht/table/occupancy_filter.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

struct ProbeStats {
  std::uint64_t longestProbe = 0;                  // slots past its home an entry sits, at most
  std::vector<std::uint64_t> displacementHistogram;  // [k] = entries k slots past their home
  double meanHitSlots = 0.0;   // slots a look-up of a stored key reads, on average
  double meanMissSlots = 0.0;  // slots a look-up of an absent key reads (kMissSamples keys, each
                               // coordinate uniform within the held keys' range)
};

class LatticeHashTable {
 public:
  // Its entry in the form list (lht/table/table_forms.hpp).
  static constexpr std::string_view kFormName = "hashed";
  static constexpr std::string_view kFormSummary = "hashed (open-addressed: key, payload)";
  static constexpr bool kInFiles = true;  // as version 4 (and 1-3, read): lht/file/lht_file.cpp
  static LatticeHashTable fromHits(const RasterHits& hits, const std::array<int, 3>& /*cells*/,
                                   LhtPrecision precision) {
    return LatticeHashTable(hits, precision);
  }
  // `lattice lht-info`'s lines: layout, load, bytes, probe lengths.
  std::vector<std::string> describe(std::uint64_t hits) const;

  static constexpr double kMaxLoad = 0.7;
  static constexpr int kMissSamples = 4096;
  static constexpr std::uint64_t kMaxCapacity = std::uint64_t(1) << 32;  // homeOf's 32-bit product

  LatticeHashTable() = default;
  // Builds from rasterized hits (distinct keys), each stored at `precision`.
  explicit LatticeHashTable(const RasterHits& hits, LhtPrecision precision = LhtPrecision::Thesis,
                            double maxLoad = kMaxLoad);
  // An empty table sized for `entries`, filled with insert().
  LatticeHashTable(LhtPrecision precision, std::uint64_t entries, double maxLoad = kMaxLoad);
  // Adopts slots read from a file (slotBytes.size() == capacity *
  // slotStride(precision)); throws lattice::Error(Input) if they are not a
  // well-formed table (fewer than 2 slots, no empty slot, an entry
  // its look-up would not reach, a count that differs).
  LatticeHashTable(LhtPrecision precision, std::vector<std::uint8_t> slotBytes, std::uint64_t capacity,
                   std::uint64_t entryCount);

  // Reads slots that stay where they are (a baked table in the firmware's
  // flash, docs/firmware.md): no copy, checked like a file's; `slotBytes`
  // must outlive the table.
  static LatticeHashTable inPlace(LhtPrecision precision, std::span<const std::uint8_t> slotBytes,
                                  std::uint64_t capacity, std::uint64_t entryCount);

  // Stores one entry (slotStride() bytes: key then payload) whose key is not
  // yet held; throws lattice::Error(Input) on a repeated key or a full table.
  void insert(const std::uint8_t* entry);

  std::optional<LhtHit> find(const LatticePoint& in, const LatticePoint& out) const;
  // The stored entry's bytes (slotStride() of them: key then payload; null
  // if absent): fixed-point rendering decodes the payload with
  // decodePayloadIntegers() instead of through LhtHit's doubles.
  const std::uint8_t* findEntry(const LatticePoint& in, const LatticePoint& out) const {
    if (in == out) return nullptr;
    const std::uint64_t key = keyOf(in, out);
    return filter_.mayHold(key) ? findKey(key) : nullptr;
  }
  // The same for a key as one integer (keyOf); never the empty key 0. Out
  // of line: inlined into the lattice leaf it measured no faster (Plate 7,
  // 5 runs: 0.34 s against 0.33 s), and on its own it shows in a profile.
  [[gnu::noinline]] const std::uint8_t* findKey(std::uint64_t key) const {
    if (capacity_ == 0) return nullptr;
    const std::uint8_t* base = slotView().data();
    for (std::uint64_t i = homeOf(key, capacity_);;) {
      const std::uint8_t* e = base + i * stride_;
      const std::uint64_t held = loadKey(e);
      // Ordered: a smaller key (or the empty slot's 0) is where `key` would sit.
      if (held <= key) return held == key ? e : nullptr;
      if (++i == capacity_) i = 0;
    }
  }
  // The entry's payload (payloadBytes(precision()) bytes after the key); null if absent.
  const std::uint8_t* findPayload(const LatticePoint& in, const LatticePoint& out) const {
    const std::uint8_t* e = findEntry(in, out);
    return e ? e + kEntryKeyBytes : nullptr;
  }

  LhtPrecision precision() const { return precision_; }
  std::size_t entryStride() const { return stride_; }
  std::uint64_t entryCount() const { return entries_; }
  std::uint64_t capacity() const { return capacity_; }
  std::uint64_t bytes() const { return slotView().size(); }
  double loadFactor() const { return capacity_ ? double(entries_) / double(capacity_) : 0.0; }
  double bytesPerEntry() const { return entries_ ? double(bytes()) / double(entries_) : 0.0; }
  ProbeStats probeStats() const;
  // Every slot, capacity() of them, entryStride() bytes each: the file's bytes.
  // (The owned copy; empty for a table read in place.)
  const std::vector<std::uint8_t>& slotBytes() const { return slots_; }
  // The slots wherever they are.
  std::span<const std::uint8_t> slotView() const { return inPlace_.data() ? inPlace_ : std::span<const std::uint8_t>(slots_); }

  // Bytes per slot: the entry without the chained layout's overflow index.
  static std::size_t slotStride(LhtPrecision precision) { return entryBytes(precision) - kEntryNextBytes; }
  // The slots a table of `entries` keys has: at least 2, with at least one
  // slot empty (a miss's probe always ends).
  static std::uint64_t capacityFor(std::uint64_t entries, double maxLoad = kMaxLoad);
  // The bytes a table of `entries` hits takes, before it is built (a memory
  // budget chooses the precision with it): exact, the layout depending on
  // the count alone.
  static std::uint64_t expectedBytes(std::uint64_t entries, LhtPrecision precision, double maxLoad = kMaxLoad);
  // What a table built for `entries` holds in memory: the slots and the
  // occupancy bitmap in front of them (the memory plan's figure).
  static std::uint64_t expectedMemory(std::uint64_t entries, LhtPrecision precision) {
    return expectedBytes(entries, precision) + OccupancyFilter::bytesFor(entries);
  }
  // The occupancy bitmap (empty for a table read in place).
  const OccupancyFilter& filter() const { return filter_; }

  // The key's six bytes as one integer (slot byte b in bits 8b..8b+7).
  static std::uint64_t keyOf(const LatticePoint& in, const LatticePoint& out) {
    return std::uint64_t(in.x) | std::uint64_t(in.y) << 8 | std::uint64_t(in.z) << 16 | std::uint64_t(out.x) << 24 |
           std::uint64_t(out.y) << 32 | std::uint64_t(out.z) << 40;
  }
  static std::uint64_t loadKey(const std::uint8_t* slot) {
    return std::uint64_t(loadLittleEndian32(slot)) | std::uint64_t(slot[4]) << 32 | std::uint64_t(slot[5]) << 40;
  }
  // The key's home slot in a table of `capacity` (< 2^32) slots.
  static std::uint64_t homeOf(std::uint64_t key, std::uint64_t capacity) {
    return ((key * 0x9E3779B97F4A7C15ull) >> 32) * capacity >> 32;
  }

 private:
  std::uint8_t* slot(std::uint64_t index) { return slots_.data() + index * stride_; }
  // insert()'s probe and displacement for a slot of kStride bytes (0: stride_).
  template <std::size_t kStride>
  void place(const std::uint8_t* entry, std::uint64_t key);
  void checkSlots() const;
  void fillFilter();

  LhtPrecision precision_ = LhtPrecision::Thesis;
  std::size_t stride_ = slotStride(LhtPrecision::Thesis);
  std::vector<std::uint8_t> slots_;        // capacity_ slots
  std::span<const std::uint8_t> inPlace_;  // instead of slots_, for a table read in place
  std::uint64_t capacity_ = 0;
  std::uint64_t entries_ = 0;
  OccupancyFilter filter_;  // every held key's bit set; empty for a table read in place
};

}  // namespace lattice::lht
