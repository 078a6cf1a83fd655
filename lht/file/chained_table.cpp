#include "lht/file/chained_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "foundation/error.hpp"

namespace lattice::lht {

std::uint64_t chainedBucketOf(const std::uint8_t key[6], std::uint64_t bucketCount) {
  const std::uint64_t k = LatticeHashTable::loadKey(key);
  const std::uint64_t h = (k * 0x9E3779B97F4A7C15ull) ^ ((k * 0x9E3779B97F4A7C15ull) >> 29);
  return h % bucketCount;
}

LatticeHashTable readChainedTable(LhtPrecision precision, std::span<const std::uint8_t> slotBytes,
                                  std::uint64_t buckets, std::uint64_t entries) {
  const std::size_t stride = entryBytes(precision);
  if (slotBytes.size() % stride != 0)
    throw Error(ErrorKind::Input, fmt::format("LHT slot bytes ({}) are not a whole number of {}-byte entries",
                                              slotBytes.size(), stride));
  const std::uint64_t slots = slotBytes.size() / stride;
  if (buckets == 0 || buckets > slots)
    throw Error(ErrorKind::Input, fmt::format("LHT bucket count {} does not fit its {} slots", buckets, slots));
  if (entries > slots)
    throw Error(ErrorKind::Input, fmt::format("LHT header says {} entries in {} slots", entries, slots));
  auto slot = [&](std::uint64_t i) { return slotBytes.data() + i * stride; };
  auto nextOf = [&](std::uint64_t i) { return loadLittleEndian32(slot(i) + stride - kEntryNextBytes); };
  LatticeHashTable table(precision, entries);
  // Every overflow slot must be reached exactly once, from a chain whose keys
  // all hash to that chain's bucket; then the old look-ups could not loop or stray.
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(slots - buckets), 0);
  std::uint64_t counted = 0;
  for (std::uint64_t b = 0; b < buckets; ++b) {
    if (LatticeHashTable::loadKey(slot(b)) == 0) {
      if (nextOf(b) != kNoNext)
        throw Error(ErrorKind::Input, fmt::format("LHT bucket {} is empty but links to an overflow entry", b));
      continue;
    }
    for (std::uint64_t index = b;;) {
      if (chainedBucketOf(slot(index), buckets) != b)
        throw Error(ErrorKind::Input, fmt::format("LHT entry in bucket {} has a key that hashes elsewhere", b));
      if (++counted > entries)
        throw Error(ErrorKind::Input, fmt::format("LHT holds more reachable entries than its header's {}", entries));
      table.insert(slot(index));
      const std::uint32_t next = nextOf(index);
      if (next == kNoNext) break;
      if (next < buckets || next >= slots || seen[static_cast<std::size_t>(next - buckets)])
        throw Error(ErrorKind::Input, fmt::format("LHT overflow index {} in bucket {}'s chain is out of range or "
                                                  "shared", next, b));
      seen[static_cast<std::size_t>(next - buckets)] = 1;
      index = next;
    }
  }
  if (std::find(seen.begin(), seen.end(), 0) != seen.end())
    throw Error(ErrorKind::Input, "LHT overflow area holds entries no chain reaches");
  if (counted != entries)
    throw Error(ErrorKind::Input,
                fmt::format("LHT holds {} reachable entries but its header says {}", counted, entries));
  return table;
}

}  // namespace lattice::lht
