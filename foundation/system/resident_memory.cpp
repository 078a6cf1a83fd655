#include "foundation/system/resident_memory.hpp"

#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace lattice {

namespace {

// "VmRSS:\t    8212 kB" -> 8212 * 1024
std::optional<std::uint64_t> statusField(std::string_view status, std::string_view name) {
  std::size_t at = 0;
  while (at < status.size()) {
    const std::size_t end = std::min(status.find('\n', at), status.size());
    const std::string_view line = status.substr(at, end - at);
    at = end + 1;
    if (line.size() <= name.size() || line.substr(0, name.size()) != name || line[name.size()] != ':') continue;
    std::string_view value = line.substr(name.size() + 1);
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.front()))) value.remove_prefix(1);
    std::uint64_t kib = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), kib);
    if (ec != std::errc() || std::string_view(ptr, value.data() + value.size()).find("kB") == std::string_view::npos)
      return std::nullopt;
    return kib * 1024;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ResidentMemory> parseProcStatus(std::string_view status) {
  const auto current = statusField(status, "VmRSS");
  const auto peak = statusField(status, "VmHWM");
  if (!current || !peak) return std::nullopt;
  return ResidentMemory{*current, *peak};
}

std::optional<std::uint64_t> physicalMemory() {
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && pageSize > 0) return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize);
#endif
  return std::nullopt;
}

std::optional<ResidentMemory> residentMemory() {
  std::ifstream in("/proc/self/status");
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return parseProcStatus(text.str());
}

}  // namespace lattice
