#include "devices/tek4125/tek4125_strategy.hpp"

#include "devices/tek4125/named_table.hpp"

namespace lattice::tek4125 {

const std::vector<Tek4125NamedStrategy>& tek4125Strategies() {
  // Fields: skipBackground, rectangles, mergeRows, runLength, shortest.
  static const std::vector<Tek4125NamedStrategy> all = {
      {"shortest", {true, true, true, true, true}},      // every candidate below that can win, smallest kept
      {"plain", {false, false, false, false, false}},    // one raster write per row
      {"skip", {true, false, false, false, false}},      // background runs left out
      {"rectangles", {false, true, false, false, false}},  // long runs as RR
      {"spans", {true, true, true, false, false}},       // skip + RR merged down rows (the default before the planner)
      {"runs", {true, true, true, true, false}},         // spans + RL run-length writes
  };
  return all;
}

std::string tek4125StrategyNames() { return namesOf(tek4125Strategies()); }

const Tek4125NamedStrategy& tek4125Strategy(std::string_view name) {
  return findNamed(tek4125Strategies(), name, "driver strategy");
}

}  // namespace lattice::tek4125
