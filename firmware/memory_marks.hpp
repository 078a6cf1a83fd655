#pragma once
// Peak RAM of a firmware run, measured, not estimated: the heap's high-water
// mark is the furthest _sbrk ever moved the break (firmware/runtime.cpp);
// the stack's is found by painting the stack with a pattern at reset and, at
// the end, looking for the deepest word that no longer holds it.
#include <cstddef>

namespace lattice::firmware {

struct MemoryMarks {
  std::size_t data = 0, bss = 0;          // static sizes (the link)
  std::size_t heapPeak = 0, heapLimit = 0;  // bytes from the heap's start
  std::size_t stackPeak = 0, stackSize = 0;
  std::size_t total() const { return data + bss + heapPeak + stackPeak; }
};

void paintStack();
MemoryMarks memoryMarks();
// Called by _sbrk.
void noteHeapBreak(std::size_t bytesFromStart);

}  // namespace lattice::firmware
