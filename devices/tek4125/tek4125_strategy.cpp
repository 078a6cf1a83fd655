#include "devices/tek4125/tek4125_strategy.hpp"

#include <fmt/format.h>

#include "util/error.hpp"

namespace lattice {

const std::vector<Tek4125NamedStrategy>& tek4125Strategies() {
  // Fields: skipBackground, rectangles, mergeRows, runLength, shortest.
  static const std::vector<Tek4125NamedStrategy> all = {
      {"shortest", {true, true, true, true, true}},      // every candidate below that can win, smallest kept
      {"plain", {false, false, false, false, false}},    // one raster write per row
      {"skip", {true, false, false, false, false}},      // background runs left out
      {"rectangles", {false, true, false, false, false}},  // long runs as RR
      {"spans", {true, true, true, false, false}},       // skip + RR merged down rows (the pre-issue-14 default)
      {"runs", {true, true, true, true, false}},         // spans + RL run-length writes
  };
  return all;
}

std::string tek4125StrategyNames() {
  std::string names;
  for (const auto& s : tek4125Strategies()) names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

const Tek4125NamedStrategy& tek4125Strategy(std::string_view name) {
  for (const auto& s : tek4125Strategies())
    if (s.name == name) return s;
  throw Error(ErrorKind::Usage,
              fmt::format("tek4125 profile: strategy={} is unknown; use one of {}", name, tek4125StrategyNames()));
}

}  // namespace lattice
