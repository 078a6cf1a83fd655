#include "foundation/error.hpp"

#include <fmt/format.h>

namespace lattice {

std::string locate(const std::string& path, long line, long column, const std::string& message) {
  if (line <= 0) return fmt::format("{}: {}", path, message);
  if (column <= 0) return fmt::format("{}:{}: {}", path, line, message);
  return fmt::format("{}:{}:{}: {}", path, line, column, message);
}

}  // namespace lattice
