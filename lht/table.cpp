#include "lht/table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "util/error.hpp"

namespace lattice::lht {

namespace {

// An empty primary slot has an all-zero key: (0,0,0)->(0,0,0) has p_i == p_o,
// a point rather than a segment, so it is never a hit.
bool isEmpty(const LhtEntry& e) {
  for (std::uint8_t b : e.key)
    if (b) return false;
  return true;
}

std::uint32_t nextOf(const LhtEntry& e) {
  return std::uint32_t(e.next[0]) | std::uint32_t(e.next[1]) << 8 | std::uint32_t(e.next[2]) << 16 |
         std::uint32_t(e.next[3]) << 24;
}

void setNext(LhtEntry& e, std::uint32_t next) {
  for (int b = 0; b < 4; ++b) e.next[b] = static_cast<std::uint8_t>(next >> (8 * b));
}

void makeKey(const LatticePoint& in, const LatticePoint& out, std::uint8_t key[6]) {
  key[0] = in.x, key[1] = in.y, key[2] = in.z, key[3] = out.x, key[4] = out.y, key[5] = out.z;
}

}  // namespace

std::uint8_t quantizeS(double s) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0, 1.0) * 255.0));
}

std::int8_t quantizeNormalComponent(double n) {
  return static_cast<std::int8_t>(std::lround(std::clamp(n, -1.0, 1.0) * 127.0));
}

LhtEntry encodeEntry(const RasterHit& hit) {
  LhtEntry e{};
  makeKey(hit.in, hit.out, e.key);
  e.s = quantizeS(hit.s);
  for (int a = 0; a < 3; ++a) e.normal[a] = quantizeNormalComponent(hit.normal[a]);
  setNext(e, kNoNext);
  return e;
}

LhtHit decodeEntry(const LhtEntry& entry) {
  LhtHit hit;
  hit.s = entry.s / 255.0;
  const Vec3d n(entry.normal[0], entry.normal[1], entry.normal[2]);
  const double length = glm::length(n);
  // Renormalize: quantizing each component separately shortens or lengthens it.
  hit.normal = length > 0.0 ? n / length : Vec3d(0, 0, 1);
  return hit;
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

LatticeHashTable::LatticeHashTable(const std::vector<RasterHit>& hits, double loadFactor) {
  if (!(loadFactor > 0.0)) throw Error(ErrorKind::Usage, "the LHT load factor must be positive");
  entries_ = hits.size();
  if (entries_ >= kNoNext) throw Error(ErrorKind::Input, "too many lattice hits for a 4-byte overflow index");
  buckets_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(double(entries_) / loadFactor)));
  slots_.assign(buckets_, LhtEntry{});
  for (LhtEntry& e : slots_) setNext(e, kNoNext);
  for (const RasterHit& hit : hits) {
    LhtEntry e = encodeEntry(hit);
    LhtEntry& head = slots_[bucketOf(e.key, buckets_)];
    if (isEmpty(head)) {
      std::memcpy(head.key, e.key, sizeof e.key);
      head.s = e.s;
      std::memcpy(head.normal, e.normal, sizeof e.normal);
      continue;  // keeps head.next
    }
    // Push onto the front of the chain: the primary slot links to the newest
    // overflow entry, which links to the older ones.
    setNext(e, nextOf(head));
    setNext(head, static_cast<std::uint32_t>(slots_.size()));
    slots_.push_back(e);  // invalidates `head`; not used after this
  }
}

LatticeHashTable::LatticeHashTable(std::vector<LhtEntry> slots, std::uint64_t bucketCount, std::uint64_t entryCount)
    : slots_(std::move(slots)), buckets_(bucketCount), entries_(entryCount) {
  if (buckets_ == 0 || buckets_ > slots_.size())
    throw Error(ErrorKind::Input, fmt::format("LHT bucket count {} does not fit its {} slots", buckets_, slots_.size()));
  // Every overflow slot must be reached exactly once, from a chain whose keys
  // all hash to that chain's bucket; then lookups cannot loop or stray.
  std::vector<std::uint8_t> seen(slots_.size() - buckets_, 0);
  std::uint64_t counted = 0;
  for (std::uint64_t b = 0; b < buckets_; ++b) {
    const LhtEntry* e = &slots_[b];
    if (isEmpty(*e)) {
      if (nextOf(*e) != kNoNext)
        throw Error(ErrorKind::Input, fmt::format("LHT bucket {} is empty but links to an overflow entry", b));
      continue;
    }
    for (;;) {
      if (bucketOf(e->key, buckets_) != b)
        throw Error(ErrorKind::Input, fmt::format("LHT entry in bucket {} has a key that hashes elsewhere", b));
      ++counted;
      const std::uint32_t next = nextOf(*e);
      if (next == kNoNext) break;
      if (next < buckets_ || next >= slots_.size() || seen[next - buckets_])
        throw Error(ErrorKind::Input, fmt::format("LHT overflow index {} in bucket {}'s chain is out of range or "
                                                  "shared", next, b));
      seen[next - buckets_] = 1;
      e = &slots_[next];
    }
  }
  if (std::find(seen.begin(), seen.end(), 0) != seen.end())
    throw Error(ErrorKind::Input, "LHT overflow area holds entries no chain reaches");
  if (counted != entries_)
    throw Error(ErrorKind::Input,
                fmt::format("LHT holds {} reachable entries but its header says {}", counted, entries_));
}

std::optional<LhtHit> LatticeHashTable::find(const LatticePoint& in, const LatticePoint& out) const {
  const LhtEntry* e = findEntry(in, out);
  if (!e) return std::nullopt;
  return decodeEntry(*e);
}

const LhtEntry* LatticeHashTable::findEntry(const LatticePoint& in, const LatticePoint& out) const {
  if (buckets_ == 0 || in == out) return nullptr;
  std::uint8_t key[6];
  makeKey(in, out, key);
  std::uint32_t index = static_cast<std::uint32_t>(bucketOf(key, buckets_));
  while (index != kNoNext) {
    const LhtEntry& e = slots_[index];
    if (std::memcmp(e.key, key, sizeof key) == 0) return &e;
    index = nextOf(e);
  }
  return nullptr;
}

ChainStats LatticeHashTable::chainStats() const {
  ChainStats stats;
  for (std::uint64_t b = 0; b < buckets_; ++b) {
    std::uint64_t length = 0;
    if (!isEmpty(slots_[b]))
      for (std::uint32_t index = static_cast<std::uint32_t>(b); index != kNoNext; index = nextOf(slots_[index])) ++length;
    if (length) ++stats.usedBuckets;
    stats.longestChain = std::max(stats.longestChain, length);
    if (stats.chainLengthHistogram.size() <= length) stats.chainLengthHistogram.resize(length + 1, 0);
    ++stats.chainLengthHistogram[length];
  }
  return stats;
}

}  // namespace lattice::lht
