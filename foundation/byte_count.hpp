#pragma once
// Sizes in bytes as people type and read them: "8MiB", "8192K", "57600".
//
// Method: a decimal number and an optional suffix; K, M and G, with or
// without "B" or "iB", are all powers of 1024, as the 8 MB of a Sun 3/60
// were. Text is refused with the forms accepted, never guessed at, so NaN,
// infinities, zero and negative sizes fail here once for every flag and
// setting that takes a size (foundation/settings_schema.hpp's Bytes rows).
#include <cstdint>
#include <string>
#include <string_view>

namespace lattice {

// "8388608", "8192K", "8KiB", "8M", "8MiB", "1.5M", "2G" -> bytes (1 to 1e18).
// lattice::Error(Usage) naming `what` (a flag or key) and the forms accepted.
std::uint64_t parseByteCount(std::string_view text, std::string_view what);
// Why `text` is refused, or "" when it is a size: for callers that report
// through another channel (CLI11's checks).
std::string byteCountProblem(std::string_view text);
// 8650752 -> "8.25 MiB", 4000 -> "3.9 KiB": for people, rounded.
std::string formatBytes(std::uint64_t bytes);
// 67108864 -> "64MiB", 57344 -> "56KiB", 57600 -> "57600": exact, and read
// back by parseByteCount as the same count (a default in --help, describe()).
std::string byteCountText(std::uint64_t bytes);

}  // namespace lattice
