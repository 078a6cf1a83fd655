#include "devices/stream_decoder.hpp"

#include <fmt/format.h>

namespace lattice {

std::string DecodeReport::summary() const {
  std::string s = fmt::format("bytes: {}\ncommands: {}\nunknown commands: {}\nmalformed: {}\n", bytes, commands,
                              unknownCommands, malformed);
  for (const auto& [name, count] : unknownByName) s += fmt::format("  unknown {}: {}\n", name, count);
  s += fmt::format("pixel work: {}{}\n", pixelWork, overBudget ? " (over the budget: drawing stopped)" : "");
  return s;
}

}  // namespace lattice
