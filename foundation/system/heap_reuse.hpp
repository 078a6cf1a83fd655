#pragma once
// Large heap blocks kept in the heap: a freed block of a megabyte (a scatter's
// 5000 node descriptions, released before its BVH is built) is then reused by
// what follows instead of returned to the kernel, whose fresh pages the next
// blocks would fault in and zero again.
//
// Method: glibc hands blocks of at least its mmap threshold (128 KiB at
// first) to mmap and unmaps them when freed; kLargeBlockThreshold raises it
// (mallopt(3), M_MMAP_THRESHOLD) once, at the start of the program. Blocks
// above it (a full-size frame, a large histogram) are still mapped alone.
// Elsewhere (no glibc) it does nothing.
#include <cstddef>

namespace lattice {

inline constexpr std::size_t kLargeBlockThreshold = std::size_t(32) << 20;  // bytes

// Call once, before the first large allocation. Returns whether the
// allocator took the setting.
bool keepLargeBlocksInHeap();

}  // namespace lattice
