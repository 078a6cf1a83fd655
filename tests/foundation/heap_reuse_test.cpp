// Large blocks stay in the heap once foundation/system/heap_reuse.hpp's
// setting is made: a megabyte block is no mapping of its own (glibc counts
// those in mallinfo2().hblks), so freeing it leaves its pages for the next
// block.
#include <catch2/catch.hpp>

#include <cstdlib>

#include "foundation/system/heap_reuse.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace lattice;

TEST_CASE("heap reuse: a megabyte block comes from the heap, not a mapping of its own", "[heap]") {
#if !defined(__GLIBC__) || defined(LATTICE_SANITIZED)
  WARN("not glibc's allocator (or a sanitizer's): skipped");
#else
  REQUIRE(keepLargeBlocksInHeap());
  const std::size_t mappedBefore = mallinfo2().hblks;
  void* block = std::malloc(std::size_t(1) << 20);
  REQUIRE(block != nullptr);
  CHECK(mallinfo2().hblks == mappedBefore);
  std::free(block);
  void* huge = std::malloc(kLargeBlockThreshold + (std::size_t(1) << 20));  // above it: still mapped alone
  REQUIRE(huge != nullptr);
  CHECK(mallinfo2().hblks == mappedBefore + 1);
  std::free(huge);
#endif
}
