#include "lht/table/hash_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "foundation/error.hpp"

namespace lattice::lht {

namespace {
constexpr int kPrefetchAhead = 16;  // hits; measured on the hair at f_lat 3 (docs/benchmarks.md, step 7)
}  // namespace

std::uint64_t LatticeHashTable::capacityFor(std::uint64_t entries, double maxLoad) {
  if (!(maxLoad > 0.0 && maxLoad < 1.0))
    throw Error(ErrorKind::Usage, fmt::format("the LHT load limit must lie strictly between 0 and 1, not {}", maxLoad));
  const auto wanted = static_cast<std::uint64_t>(std::ceil(double(entries) / maxLoad));
  return std::max<std::uint64_t>({2, wanted, entries + 1});
}

std::uint64_t LatticeHashTable::expectedBytes(std::uint64_t entries, LhtPrecision precision, double maxLoad) {
  return capacityFor(entries, maxLoad) * slotStride(precision);
}

LatticeHashTable::LatticeHashTable(LhtPrecision precision, std::uint64_t entries, double maxLoad)
    : precision_(precision), stride_(slotStride(precision)) {
  capacity_ = capacityFor(entries, maxLoad);
  if (capacity_ >= kMaxCapacity) throw Error(ErrorKind::Input, "too many lattice hits for one table (2^32 slots)");
  slots_.assign(static_cast<std::size_t>(capacity_ * stride_), 0);
  filter_ = OccupancyFilter(entries);
}

LatticeHashTable::LatticeHashTable(const RasterHits& hits, LhtPrecision precision, double maxLoad)
    : LatticeHashTable(precision, hits.size(), maxLoad) {
  std::vector<std::uint8_t> entry(entryBytes(precision));
  // Homes are random: while one hit is placed, the home slot of the hit
  // kPrefetchAhead places on is already being fetched (a no-op where the
  // target has no prefetch, as the Cortex-M3).
  auto ahead = hits.begin();
  const auto fetch = [&] {
    if (ahead == hits.end()) return;
    __builtin_prefetch(slot(homeOf(keyOf(ahead->in, ahead->out), capacity_)), 1);
    ++ahead;
  };
  for (int n = 0; n < kPrefetchAhead; ++n) fetch();
  for (const RasterHit& hit : hits) {
    fetch();
    encodeEntry(hit, precision_, entry.data());
    insert(entry.data());
  }
}

void LatticeHashTable::insert(const std::uint8_t* entry) {
  const std::uint64_t key = loadKey(entry);
  if (key == 0) throw Error(ErrorKind::Input, "an LHT entry with the empty key (0,0,0)->(0,0,0)");
  if (entries_ + 1 >= capacity_) throw Error(ErrorKind::Input, "more LHT entries than the table was sized for");
  filter_.add(key);  // before the loop carries smaller keys on under `key`
  // Each precision's slot size as a constant, so each copy and swap of a
  // slot is a few moves instead of a call (a scatter's table is tens of
  // thousands of inserts); any other size takes the general loop.
  switch (stride_) {
    case 9: return place<9>(entry, key);
    case 10: return place<10>(entry, key);
    case 12: return place<12>(entry, key);
    default: return place<0>(entry, key);
  }
}

template <std::size_t kStride>
void LatticeHashTable::place(const std::uint8_t* entry, std::uint64_t key) {
  const std::size_t stride = kStride ? kStride : stride_;
  std::uint8_t carried[32];  // the entry being placed: the new one, then each smaller one it displaces
  static_assert(sizeof carried >= 16);
  std::memcpy(carried, entry, stride);
  for (std::uint64_t i = homeOf(key, capacity_);; i = i + 1 == capacity_ ? 0 : i + 1) {
    std::uint8_t* at = slot(i);
    const std::uint64_t held = loadKey(at);
    if (held > key) continue;
    if (held == key) throw Error(ErrorKind::Input, fmt::format("LHT key {:012x} stored twice", key));
    if (held == 0) {
      std::memcpy(at, carried, stride);
      ++entries_;
      return;
    }
    // A smaller key: ours takes its place and it moves on (its run so far
    // holds only larger keys, ours now among them).
    std::uint8_t displaced[32];
    std::memcpy(displaced, at, stride);
    std::memcpy(at, carried, stride);
    std::memcpy(carried, displaced, stride);
    key = held;
  }
}

LatticeHashTable::LatticeHashTable(LhtPrecision precision, std::vector<std::uint8_t> slotBytes, std::uint64_t capacity,
                                   std::uint64_t entryCount)
    : precision_(precision), stride_(slotStride(precision)), slots_(std::move(slotBytes)), capacity_(capacity),
      entries_(entryCount) {
  checkSlots();
  fillFilter();
}

void LatticeHashTable::fillFilter() {
  filter_ = OccupancyFilter(entries_);
  const std::uint8_t* base = slotView().data();
  for (std::uint64_t i = 0; i < capacity_; ++i)
    if (const std::uint64_t key = loadKey(base + i * stride_)) filter_.add(key);
}

LatticeHashTable LatticeHashTable::inPlace(LhtPrecision precision, std::span<const std::uint8_t> slotBytes,
                                           std::uint64_t capacity, std::uint64_t entryCount) {
  LatticeHashTable table;
  table.precision_ = precision;
  table.stride_ = slotStride(precision);
  table.inPlace_ = slotBytes;
  table.entries_ = entryCount;
  table.capacity_ = capacity;
  table.checkSlots();
  return table;
}

void LatticeHashTable::checkSlots() const {
  if (capacity_ < 2 || capacity_ >= kMaxCapacity)
    throw Error(ErrorKind::Input, fmt::format("LHT capacity {} is outside 2 to 2^32 - 1 slots", capacity_));
  if (bytes() / stride_ != capacity_ || bytes() % stride_ != 0)
    throw Error(ErrorKind::Input, fmt::format("LHT slot bytes ({}) are not {} slots of {} bytes", bytes(), capacity_,
                                              stride_));
  if (entries_ >= capacity_)
    throw Error(ErrorKind::Input, fmt::format("LHT says {} entries in {} slots: no slot is left empty to end a "
                                              "probe", entries_, capacity_));
  // Every held key must be the one its own look-up finds: then no empty slot
  // lies between it and its home, and no key is held twice. Look-ups end:
  // at least one slot is empty (counted below).
  const std::uint8_t* base = slotView().data();
  std::uint64_t held = 0;
  for (std::uint64_t i = 0; i < capacity_; ++i) {
    const std::uint64_t key = loadKey(base + i * stride_);
    if (key == 0) continue;
    ++held;
    if ((key & 0xffffff) == key >> 24)
      throw Error(ErrorKind::Input, fmt::format("LHT slot {} holds a point, not a segment (p_i == p_o)", i));
    if (findKey(key) != base + i * stride_)
      throw Error(ErrorKind::Input, fmt::format("LHT slot {} holds a key its look-up does not reach (misplaced or "
                                                "repeated)", i));
  }
  if (held != entries_)
    throw Error(ErrorKind::Input, fmt::format("LHT holds {} entries but its header says {}", held, entries_));
}

std::optional<LhtHit> LatticeHashTable::find(const LatticePoint& in, const LatticePoint& out) const {
  const std::uint8_t* e = findEntry(in, out);
  if (!e) return std::nullopt;
  return decodeEntry(e, precision_);
}

ProbeStats LatticeHashTable::probeStats() const {
  ProbeStats stats;
  if (capacity_ == 0) return stats;
  const std::uint8_t* base = slotView().data();
  auto keyAt = [&](std::uint64_t i) { return loadKey(base + i * stride_); };
  std::uint64_t hitSlots = 0;
  for (std::uint64_t i = 0; i < capacity_; ++i) {
    const std::uint64_t key = keyAt(i);
    if (key == 0) continue;
    const std::uint64_t d = (i + capacity_ - homeOf(key, capacity_)) % capacity_;
    hitSlots += d + 1;
    stats.longestProbe = std::max(stats.longestProbe, d);
    if (stats.displacementHistogram.size() <= d) stats.displacementHistogram.resize(static_cast<std::size_t>(d) + 1, 0);
    ++stats.displacementHistogram[static_cast<std::size_t>(d)];
  }
  stats.meanHitSlots = entries_ ? double(hitSlots) / double(entries_) : 0.0;
  // Misses: absent keys whose coordinates lie in the held keys' ranges (as
  // a render's do), from a fixed-seed xorshift; the slots each look-up reads.
  std::uint64_t top[6] = {};  // per key byte, the largest value held
  for (std::uint64_t i = 0; i < capacity_; ++i)
    for (int b = 0; b < 6; ++b) top[b] = std::max(top[b], keyAt(i) >> 8 * b & 0xff);
  std::uint64_t state = 0x2545F4914F6CDD1Dull, missSlots = 0, misses = 0;
  for (int n = 0; n < kMissSamples * 4 && misses < kMissSamples; ++n) {
    std::uint64_t key = 0;
    for (int b = 0; b < 6; ++b) {
      state ^= state << 13, state ^= state >> 7, state ^= state << 17;
      key |= (state % (top[b] + 1)) << 8 * b;
    }
    if ((key & 0xffffff) == key >> 24 || findKey(key)) continue;
    std::uint64_t i = homeOf(key, capacity_), slots = 1;
    for (; keyAt(i) > key; i = i + 1 == capacity_ ? 0 : i + 1) ++slots;
    missSlots += slots, ++misses;
  }
  stats.meanMissSlots = misses ? double(missSlots) / double(misses) : 0.0;
  return stats;
}

std::vector<std::string> LatticeHashTable::describe(std::uint64_t /*hits*/) const {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("layout:        open addressing, linear probing, {} slots", capacity()));
  lines.push_back(fmt::format("load factor:   {:.3f} of the slots used", loadFactor()));
  lines.push_back(fmt::format("table bytes:   {} ({:.2f} bytes/entry, {} bytes per slot)", bytes(), bytesPerEntry(),
                              entryStride()));
  const ProbeStats probes = probeStats();
  lines.push_back(fmt::format("probes:        a hit reads {:.2f} slots on average, a miss {:.2f}; longest displacement {}",
                              probes.meanHitSlots, probes.meanMissSlots, probes.longestProbe));
  lines.push_back(fmt::format("occupancy:     a bitmap of {} bits ({} bytes) in front of the slots, built on load",
                              filter_.bits(), filter_.bytes()));
  for (std::size_t k = 0; k < probes.displacementHistogram.size(); ++k)
    if (probes.displacementHistogram[k])
      lines.push_back(fmt::format("  {:>3} past home: {} entries", k, probes.displacementHistogram[k]));
  return lines;
}

}  // namespace lattice::lht
