#include "foundation/byte_count.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "foundation/error.hpp"

namespace lattice {

namespace {

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// The suffix's scale: "" and "B" 1, "K", "KB", "KiB" 1024 (any case), and M
// and G so; 0 for anything else.
double scaleOf(std::string_view suffix) {
  if (suffix.empty() || (suffix.size() == 1 && upper(suffix[0]) == 'B')) return 1.0;
  const std::string_view units = "KMG";
  const std::size_t power = units.find(upper(suffix[0]));
  if (power == std::string_view::npos) return 0.0;
  const std::string_view rest = suffix.substr(1);
  const bool tail = rest.empty() || (rest.size() == 1 && upper(rest[0]) == 'B') ||
                    (rest.size() == 2 && upper(rest[0]) == 'I' && upper(rest[1]) == 'B');
  return tail ? std::pow(1024.0, static_cast<double>(power + 1)) : 0.0;
}

// The count, or 0 when `text` is not a size.
std::uint64_t byteCountOf(std::string_view text) {
  double number = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (ec != std::errc() || !(number > 0.0) || !std::isfinite(number)) return 0;
  const double scale = scaleOf(std::string_view(ptr, static_cast<std::size_t>(text.data() + text.size() - ptr)));
  const double bytes = std::round(number * scale);
  if (bytes < 1.0 || bytes > 1e18) return 0;
  return static_cast<std::uint64_t>(bytes);
}

}  // namespace

std::string byteCountProblem(std::string_view text) {
  if (byteCountOf(text) > 0) return {};
  return fmt::format("'{}' is not a size in bytes; give a size in bytes such as 8388608, 8192K, 8MiB or 1.5M (K, M, "
                     "G with or without 'iB' are powers of 1024)",
                     text);
}

std::uint64_t parseByteCount(std::string_view text, std::string_view what) {
  const std::uint64_t bytes = byteCountOf(text);
  if (bytes == 0) throw Error(ErrorKind::Usage, fmt::format("{}: {}", what, byteCountProblem(text)));
  return bytes;
}

std::string formatBytes(std::uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (bytes >= 1024ull * 1024 * 1024) return fmt::format("{:.2f} GiB", b / (1024.0 * 1024 * 1024));
  if (bytes >= 1024ull * 1024) return fmt::format("{:.2f} MiB", b / (1024.0 * 1024));
  if (bytes >= 1024) return fmt::format("{:.1f} KiB", b / 1024.0);
  return fmt::format("{} B", bytes);
}

std::string byteCountText(std::uint64_t bytes) {
  constexpr std::uint64_t kKiB = 1024, kMiB = kKiB * 1024, kGiB = kMiB * 1024;
  if (bytes > 0 && bytes % kGiB == 0) return fmt::format("{}GiB", bytes / kGiB);
  if (bytes > 0 && bytes % kMiB == 0) return fmt::format("{}MiB", bytes / kMiB);
  if (bytes > 0 && bytes % kKiB == 0) return fmt::format("{}KiB", bytes / kKiB);
  return fmt::format("{}", bytes);
}

}  // namespace lattice
