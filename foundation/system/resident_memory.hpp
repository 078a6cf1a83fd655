#pragma once
// The process's own resident memory, as the kernel counts it for
// /usr/bin/time -v ("Maximum resident set size" is VmHWM): what
// --memory-budget is measured against (docs/memory.md).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "foundation/byte_count.hpp"  // the sizes a budget is given in

namespace lattice {

struct ResidentMemory {
  std::uint64_t current = 0;  // VmRSS, bytes
  std::uint64_t peak = 0;     // VmHWM, bytes: the high-water mark so far
};

// From /proc/self/status; nullopt where there is no procfs (the budget then
// works from its estimates alone).
std::optional<ResidentMemory> residentMemory();
// The machine's physical memory (sysconf), bytes; nullopt where unknown.
std::optional<std::uint64_t> physicalMemory();
// Parses the text of a /proc/PID/status file (nullopt if a field is missing).
std::optional<ResidentMemory> parseProcStatus(std::string_view status);


}  // namespace lattice
