#include "lht/table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

void makeKey(const LatticePoint& in, const LatticePoint& out, std::uint8_t key[kEntryKeyBytes]) {
  key[0] = in.x, key[1] = in.y, key[2] = in.z, key[3] = out.x, key[4] = out.y, key[5] = out.z;
}

}  // namespace

std::uint32_t LatticeHashTable::nextOf(std::uint64_t index) const {
  return loadLittleEndian32(slot(index) + stride_ - kEntryNextBytes);
}

void LatticeHashTable::setNext(std::uint64_t index, std::uint32_t next) {
  storeLittleEndian32(slot(index) + stride_ - kEntryNextBytes, next);
}

// An empty primary slot has an all-zero key: (0,0,0)->(0,0,0) has p_i == p_o,
// a point rather than a segment, so it is never a hit.
bool LatticeHashTable::isEmpty(std::uint64_t index) const {
  const std::uint8_t* key = slot(index);
  return std::all_of(key, key + kEntryKeyBytes, [](std::uint8_t b) { return b == 0; });
}

std::uint64_t LatticeHashTable::slotsFor(const RasterHits& hits, std::uint64_t bucketCount) {
  // Every bucket holds its first key in its primary slot; every other key of
  // the bucket takes one overflow slot.
  std::vector<bool> used(static_cast<std::size_t>(bucketCount), false);
  std::uint64_t usedBuckets = 0;
  std::uint8_t key[kEntryKeyBytes];
  for (const RasterHit& hit : hits) {
    makeKey(hit.in, hit.out, key);
    const std::uint64_t b = bucketOf(key, bucketCount);
    if (!used[static_cast<std::size_t>(b)]) used[static_cast<std::size_t>(b)] = true, ++usedBuckets;
  }
  return bucketCount + hits.size() - usedBuckets;
}

std::uint64_t LatticeHashTable::expectedBytes(std::uint64_t entries, LhtPrecision precision, double loadFactor) {
  // Keys spread like a Poisson process over the buckets (Fibonacci hashing
  // of distinct keys): a bucket is empty with probability exp(-loadFactor),
  // and only empty buckets cost a slot beyond one per entry.
  const double buckets = std::max(1.0, std::ceil(double(entries) / loadFactor));
  const double slots = double(entries) + buckets * std::exp(-loadFactor);
  return static_cast<std::uint64_t>(std::ceil(slots)) * entryBytes(precision);
}

std::uint64_t LatticeHashTable::bucketOf(const std::uint8_t key[6], std::uint64_t bucketCount) {
  std::uint64_t k = 0;
  for (int b = 0; b < 6; ++b) k |= std::uint64_t(key[b]) << (8 * b);
  // Fibonacci hashing: the multiply spreads neighbouring lattice points (keys
  // differing in one low byte) over the whole table; the shift folds the well-mixed
  // high bits into the low ones that the modulo keeps.
  const std::uint64_t h = (k * 0x9E3779B97F4A7C15ull) ^ ((k * 0x9E3779B97F4A7C15ull) >> 29);
  return h % bucketCount;
}

LatticeHashTable::LatticeHashTable(const RasterHits& hits, LhtPrecision precision, double loadFactor)
    : precision_(precision), stride_(entryBytes(precision)) {
  if (!(loadFactor > 0.0)) throw Error(ErrorKind::Usage, "the LHT load factor must be positive");
  entries_ = hits.size();
  if (entries_ >= kNoNext) throw Error(ErrorKind::Input, "too many lattice hits for a 4-byte overflow index");
  buckets_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(double(entries_) / loadFactor)));
  // The exact size first: growing the overflow area by doubling would leave
  // up to half of the table's memory allocated and unused.
  slots_.reserve(static_cast<std::size_t>(slotsFor(hits, buckets_) * stride_));
  slots_.assign(static_cast<std::size_t>(buckets_ * stride_), 0);
  for (std::uint64_t b = 0; b < buckets_; ++b) setNext(b, kNoNext);
  std::vector<std::uint8_t> entry(stride_);
  for (const RasterHit& hit : hits) {
    encodeEntry(hit, precision_, entry.data());
    const std::uint64_t head = bucketOf(entry.data(), buckets_);
    if (isEmpty(head)) {
      std::copy(entry.begin(), entry.end() - kEntryNextBytes, slot(head));  // keeps the head's next
      continue;
    }
    // Push onto the front of the chain: the primary slot links to the newest
    // overflow entry, which links to the older ones.
    const std::uint64_t added = slotCount();
    storeLittleEndian32(entry.data() + stride_ - kEntryNextBytes, nextOf(head));
    slots_.insert(slots_.end(), entry.begin(), entry.end());
    setNext(head, static_cast<std::uint32_t>(added));
  }
}

LatticeHashTable::LatticeHashTable(LhtPrecision precision, std::vector<std::uint8_t> slotBytes,
                                   std::uint64_t bucketCount, std::uint64_t entryCount)
    : precision_(precision), stride_(entryBytes(precision)), slots_(std::move(slotBytes)), buckets_(bucketCount),
      entries_(entryCount) {
  checkChains();
}

LatticeHashTable LatticeHashTable::inPlace(LhtPrecision precision, std::span<const std::uint8_t> slotBytes,
                                           std::uint64_t bucketCount, std::uint64_t entryCount) {
  LatticeHashTable table;
  table.precision_ = precision;
  table.stride_ = entryBytes(precision);
  table.inPlace_ = slotBytes;
  table.buckets_ = bucketCount;
  table.entries_ = entryCount;
  table.checkChains();
  return table;
}

void LatticeHashTable::checkChains() const {
  if (bytes() % stride_ != 0)
    throw Error(ErrorKind::Input, fmt::format("LHT slot bytes ({}) are not a whole number of {}-byte entries",
                                              bytes(), stride_));
  const std::uint64_t slots = slotCount();
  if (buckets_ == 0 || buckets_ > slots)
    throw Error(ErrorKind::Input, fmt::format("LHT bucket count {} does not fit its {} slots", buckets_, slots));
  // Every overflow slot must be reached exactly once, from a chain whose keys
  // all hash to that chain's bucket; then lookups cannot loop or stray.
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(slots - buckets_), 0);
  std::uint64_t counted = 0;
  for (std::uint64_t b = 0; b < buckets_; ++b) {
    if (isEmpty(b)) {
      if (nextOf(b) != kNoNext)
        throw Error(ErrorKind::Input, fmt::format("LHT bucket {} is empty but links to an overflow entry", b));
      continue;
    }
    for (std::uint64_t index = b;;) {
      if (bucketOf(slot(index), buckets_) != b)
        throw Error(ErrorKind::Input, fmt::format("LHT entry in bucket {} has a key that hashes elsewhere", b));
      ++counted;
      const std::uint32_t next = nextOf(index);
      if (next == kNoNext) break;
      if (next < buckets_ || next >= slots || seen[static_cast<std::size_t>(next - buckets_)])
        throw Error(ErrorKind::Input, fmt::format("LHT overflow index {} in bucket {}'s chain is out of range or "
                                                  "shared", next, b));
      seen[static_cast<std::size_t>(next - buckets_)] = 1;
      index = next;
    }
  }
  if (std::find(seen.begin(), seen.end(), 0) != seen.end())
    throw Error(ErrorKind::Input, "LHT overflow area holds entries no chain reaches");
  if (counted != entries_)
    throw Error(ErrorKind::Input,
                fmt::format("LHT holds {} reachable entries but its header says {}", counted, entries_));
}

std::optional<LhtHit> LatticeHashTable::find(const LatticePoint& in, const LatticePoint& out) const {
  const std::uint8_t* e = findEntry(in, out);
  if (!e) return std::nullopt;
  return decodeEntry(e, precision_);
}

const std::uint8_t* LatticeHashTable::findEntry(const LatticePoint& in, const LatticePoint& out) const {
  if (buckets_ == 0 || in == out) return nullptr;
  std::uint8_t key[kEntryKeyBytes];
  makeKey(in, out, key);
  std::uint32_t index = static_cast<std::uint32_t>(bucketOf(key, buckets_));
  while (index != kNoNext) {
    const std::uint8_t* e = slot(index);
    if (std::memcmp(e, key, kEntryKeyBytes) == 0) return e;
    index = nextOf(index);
  }
  return nullptr;
}

ChainStats LatticeHashTable::chainStats() const {
  ChainStats stats;
  for (std::uint64_t b = 0; b < buckets_; ++b) {
    std::uint64_t length = 0;
    if (!isEmpty(b))
      for (std::uint32_t index = static_cast<std::uint32_t>(b); index != kNoNext; index = nextOf(index)) ++length;
    if (length) ++stats.usedBuckets;
    stats.longestChain = std::max(stats.longestChain, length);
    const auto at = static_cast<std::size_t>(length);
    if (stats.chainLengthHistogram.size() <= at) stats.chainLengthHistogram.resize(at + 1, 0);
    ++stats.chainLengthHistogram[at];
  }
  return stats;
}

}  // namespace lattice::lht
