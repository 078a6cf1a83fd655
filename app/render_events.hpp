#pragma once
// What a render did along the way, told to whoever runs it: the render job
// (app/render_job.hpp) and its memory budget (app/render_budget.hpp) raise
// these events in the order they happen and never print; `lattice render`
// (app/commands/cmd_render.cpp) says them on stderr, a test or benchmark may keep or
// ignore them. An event is raised when it happens, not returned at the end,
// so that what was said before an error is still said.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "devices/device.hpp"
#include "lht/table/lht_precision.hpp"
#include "lht/leaf/lookup_stats.hpp"

namespace lattice::app {

// The scene's size did not fit the device's screen and was shrunk.
struct SizeFitted {
  int sceneWidth, sceneHeight;
  int deviceWidth, deviceHeight;
  int width, height;
};

// Under a memory budget, a lattice rasterized in another precision than asked.
struct TableRepacked {
  std::string lattice;
  lht::LhtPrecision requested, packed;
  std::uint64_t packedBytes;
};

// Under a memory budget, the plan made once the scene was built.
struct MemoryPlanned {
  std::string summary;
};

// Under a memory budget, the peak resident memory measured at the end.
struct PeakMeasured {
  std::uint64_t peak, budget;
};

// A device's stream, sent. `baud` when the device has a serial line.
struct StreamSent {
  std::string device, title;
  std::optional<int> baud;
  std::string where;
  devices::DriverStats stats;
};

// `--lht-stats`: every lattice's look-up counts (none looked up: empty).
struct LookupsCounted {
  std::vector<lht::LookupSummary> lattices;
};

// `--wire-seconds` / `--wire-bytes`: the setting the search chose, in words
// (app/wire_budget.hpp's describeWireChoice).
struct WireChosen {
  std::string description;
};

using RenderEvent =
    std::variant<SizeFitted, TableRepacked, MemoryPlanned, PeakMeasured, StreamSent, LookupsCounted, WireChosen>;
// Where events go; empty: nowhere.
using RenderEvents = std::function<void(const RenderEvent&)>;

inline void raise(const RenderEvents& events, const RenderEvent& event) {
  if (events) events(event);
}

}  // namespace lattice::app
