#include "firmware/memory_marks.hpp"

#include <cstdint>

extern "C" std::uint32_t __data_start, __data_end, __bss_start, __bss_end, __heap_start, __heap_end,
    __stack_limit, __stack_top;

namespace lattice::firmware {
namespace {

constexpr std::uint32_t kPaint = 0x5ca1ab1e;
std::size_t heapPeak = 0;

std::size_t distance(const void* from, const void* to) {
  return static_cast<std::size_t>(static_cast<const char*>(to) - static_cast<const char*>(from));
}

}  // namespace

// Runs before main with only the reset handler's frame in use: paint from the
// limit up to a little below the current stack pointer.
void paintStack() {
  std::uint32_t here = 0;
  auto* end = reinterpret_cast<std::uint32_t*>(reinterpret_cast<std::uintptr_t>(&here) & ~std::uintptr_t(7)) - 16;
  for (std::uint32_t* p = &__stack_limit; p < end; ++p) *p = kPaint;
}

void noteHeapBreak(std::size_t bytesFromStart) {
  if (bytesFromStart > heapPeak) heapPeak = bytesFromStart;
}

MemoryMarks memoryMarks() {
  MemoryMarks m;
  m.data = distance(&__data_start, &__data_end);
  m.bss = distance(&__bss_start, &__bss_end);
  m.heapPeak = heapPeak;
  m.heapLimit = distance(&__heap_start, &__heap_end);
  m.stackSize = distance(&__stack_limit, &__stack_top);
  const std::uint32_t* p = &__stack_limit;
  while (p < &__stack_top && *p == kPaint) ++p;
  m.stackPeak = distance(p, &__stack_top);
  return m;
}

}  // namespace lattice::firmware
