// Known-defect rules for the harnesses (held_back.hpp).
//
// Method and tunables:
// * scene, defect 4 (lattice_scatter accepts 10^6 instances but builds them
//   in quadratic time; one such 90-byte scene took 82 s under ASan here): any
//   `count = N` with N > kScatterCount is held back. The scan reads TOML
//   integer spellings (decimal with '_', 0x, 0o, 0b) after a "count" key,
//   a superset of what the loader accepts, so no such scene slips through.
#include "fuzz/held_back.hpp"

#include <cctype>
#include <string>

namespace lattice::fuzz {
namespace {

constexpr unsigned long long kScatterCount = 20000;

// The integer at `at` (after spaces, '=', quotes and a sign), saturating.
unsigned long long integerAt(std::string_view text, std::size_t at) {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '=' || text[at] == '"' ||
                              text[at] == '\'' || text[at] == '+'))
    ++at;
  unsigned base = 10;
  if (at + 1 < text.size() && text[at] == '0' && std::string_view("xob").find(text[at + 1]) != std::string_view::npos) {
    base = text[at + 1] == 'x' ? 16 : text[at + 1] == 'o' ? 8 : 2;
    at += 2;
  }
  unsigned long long value = 0;
  for (; at < text.size(); ++at) {
    const char c = text[at];
    if (c == '_') continue;
    unsigned digit;
    if (std::isdigit(static_cast<unsigned char>(c)))
      digit = static_cast<unsigned>(c - '0');
    else if (base == 16 && std::isxdigit(static_cast<unsigned char>(c)))
      digit = static_cast<unsigned>(std::tolower(static_cast<unsigned char>(c)) - 'a' + 10);
    else
      break;
    if (digit >= base) break;
    if (value > (~0ull - digit) / base) return ~0ull;
    value = value * base + digit;
  }
  return value;
}

bool hugeScatter(std::string_view text) {
  for (std::size_t at = text.find("count"); at != std::string_view::npos; at = text.find("count", at + 1))
    if (integerAt(text, at + 5) > kScatterCount) return true;
  return false;
}

}  // namespace

bool heldBack(std::string_view target, std::span<const std::uint8_t> bytes) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (target == "scene") return hugeScatter(text);
  return false;
}

}  // namespace lattice::fuzz
