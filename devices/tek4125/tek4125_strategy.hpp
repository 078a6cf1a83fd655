#pragma once
// How the 4125 driver spends bytes: which ways of drawing a run it may
// choose from. The form set (tek4125_forms.hpp) says what the terminal is
// trusted to draw; a strategy picks among what it allows. "shortest" (the
// default) encodes the picture with every candidate and sends the smallest
// stream; the others exist so bench/stream-bytes.sh can show what each way
// buys.
#include <string>
#include <string_view>
#include <vector>

namespace lattice::tek4125 {

struct Tek4125DriverOptions {
  bool skipBackground = true;  // runs of the background colour are not sent (painted once, or the clear)
  bool rectangles = true;      // a run may go as an RR rectangle fill
  bool mergeRows = true;       // an RR continued by the same run on the next rows grows instead
  bool runLength = true;       // runs may go as RL run codes (where the form set allows RL)
  bool shortest = true;        // also try the variants without RL and without merging; keep the smallest
};

struct Tek4125NamedStrategy {
  std::string name;
  Tek4125DriverOptions options;
};
// shortest, plain, skip, rectangles, spans, runs.
const std::vector<Tek4125NamedStrategy>& tek4125Strategies();
// Throws lattice::Error(Usage) naming the strategies.
const Tek4125NamedStrategy& tek4125Strategy(std::string_view name);
std::string tek4125StrategyNames();

}  // namespace lattice::tek4125
