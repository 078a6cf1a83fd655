// The mmap threshold raised (method: foundation/system/heap_reuse.hpp).
#include "foundation/system/heap_reuse.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lattice {

bool keepLargeBlocksInHeap() {
#if defined(__GLIBC__)
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(kLargeBlockThreshold)) == 1;
#else
  return false;
#endif
}

}  // namespace lattice
