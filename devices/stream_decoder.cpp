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

const std::string& StreamDecoder::dialogText() const {
  static const std::string none;
  return none;
}

void appendDialogText(std::string& text, std::uint8_t c) {
  // Trimmed by half at a time, so a long session costs one move per 2 KiB.
  if (text.size() >= kDialogKeepBytes) text.erase(0, kDialogKeepBytes / 2);
  text.push_back(static_cast<char>(c));
}

}  // namespace lattice
