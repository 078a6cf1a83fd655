#pragma once
// The chained table of .lht versions 1 to 3 (the thesis's sec. 2.3 layout:
// `buckets` primary slots then an overflow area, each slot the key, the
// payload and a 4-byte index of the chain's next slot), read into today's
// open-addressed table (lht/table/hash_table.hpp).
//
// Method: every chain is walked from its primary slot and checked as those
// versions' reader did (an index out of range or shared, a cycle, a key that
// hashes to another bucket: refused), and each entry is inserted in the
// order the walk meets it. The bucket of a key was Fibonacci hashing reduced
// `% buckets`; that is kept here only to check the file.
#include <cstdint>
#include <span>

#include "lht/table/hash_table.hpp"

namespace lattice::lht {

// Throws lattice::Error(Input) naming what is wrong in a malformed table.
LatticeHashTable readChainedTable(LhtPrecision precision, std::span<const std::uint8_t> slotBytes,
                                  std::uint64_t bucketCount, std::uint64_t entryCount);

// The chained layout's bucket of a key (its six bytes), as versions 1-3 hashed it.
std::uint64_t chainedBucketOf(const std::uint8_t key[6], std::uint64_t bucketCount);

}  // namespace lattice::lht
