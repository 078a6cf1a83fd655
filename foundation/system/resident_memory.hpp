#pragma once
// The process's own resident memory, as the kernel counts it for
// /usr/bin/time -v ("Maximum resident set size" is VmHWM): what
// --memory-budget is measured against (docs/memory.md).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

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

// "8388608", "8192K", "8KiB", "8M", "8MiB", "1.5M", "2G": decimal or binary
// suffixes both mean powers of 1024, as the 8 MB of a Sun 3/60 did.
// lattice::Error(Usage) naming the flag and the forms accepted.
std::uint64_t parseByteCount(std::string_view text, std::string_view flag);
// 8650752 -> "8.25 MiB", 4000 -> "3.9 KiB".
std::string formatBytes(std::uint64_t bytes);

}  // namespace lattice
