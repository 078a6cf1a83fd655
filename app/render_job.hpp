#pragma once
// "Render this scene to this device over this transport", as one library
// call: what `lattice render` does once its flags are parsed, and what tests
// and benchmarks call without a command line.
//
//   scene ─► Renderer<T> ─► quantizer ─► device driver (device table) ─► transport
//                                                         └─► emulator ─► PNG
//
// The device is any entry of devices/device_table.hpp, or none for a
// truecolour PNG. The driver's bytes go to the transport (a file written
// atomically, standard output or a serial line) and, when a picture is asked
// for, through the device's emulator on their way, so the PNG shows exactly
// the stream that was sent.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/render_events.hpp"
#include "app/render_phases.hpp"
#include "app/wire_budget.hpp"
#include "devices/device.hpp"
#include "io/serial_options.hpp"
#include "loader/lattice_definition.hpp"
#include "quantize/run_pipeline.hpp"
#include "render/renderer.hpp"

namespace lattice::app {

// Where the job's picture and stream go.
struct RenderOutput {
  std::string device;                 // a device table name, or empty for a truecolour PNG
  std::vector<std::string> settings;  // the device profile's key=value overrides
  std::string picture;                // PNG to write: truecolour, or the emulator's screen; empty: none
  std::string stream;                 // the device's bytes to a file, or "-" for standard output
  std::optional<io::SerialOptions> port;  // ... or to a serial line (io/serial_settings.hpp)
  bool baudFromProfile = false;       // the port's baud is the device profile's
};

// What the memory budget may choose, and what the user chose instead.
struct MemoryChoice {
  std::optional<std::uint64_t> budget;  // bytes of peak resident memory; unset: the default, which only refuses
  bool modeChosenByUser = false;        // the quantizer mode is the user's (not the budget's)
  bool histogramChosenByUser = false;   // and the histogram form (--histogram)
};

// A job is the stages' own settings side by side, each checked where it is
// read (the flags, a schema's --set), not a second time here.
struct RenderJob {
  std::string scene;  // scene file
  RenderOutput output;
  // The picture: size (0: the scene's, fitted to the device's screen),
  // threads (0: all cores), full ray trace, lattice shadows (render/renderer.hpp).
  RenderSettings render;
  std::string arithmetic = "double";  // an arithmetic's name (foundation/arithmetics.hpp)
  // The lattice tables' user settings (loader/table_settings.hpp), and
  // `stats` when their look-ups are to be counted and printed; the threads
  // and a budget's hooks are the job's to fill in.
  lht::TableSettings tables;
  quantize::PipelineOptions pipeline;  // quantize/pipeline_settings.hpp
  MemoryChoice memory;
  std::optional<WireBudget> wire;  // choose colours, dithering and runs to fit (app/wire_budget_settings.hpp)
  // Rate-distortion runs at a fixed lambda (quantize/rate_distortion_runs.hpp;
  // 0: lossless): a benchmark's setting (bench/wire_bench.cpp), which a wire
  // budget chooses for a user.
  double rdLambda = 0;
  bool quiet = false;   // no progress bars
  RenderEvents events;  // told what happened along the way (app/render_events.hpp); empty: nobody
};

struct RenderResult {
  int width = 0;
  int height = 0;
  double seconds = 0;    // scene set-up (tree, lattice tables), trace, output
  RenderPhases phases;  // those seconds phase by phase (app/render_phases.hpp)
  std::uint64_t rays = 0;
  unsigned threads = 0;
  std::optional<devices::DriverStats> stream;  // a device's stream
  std::string destination;                     // where the stream went, in words
  std::optional<WireSearch> wire;              // what a wire budget chose (its picture left out)
};

// Refuses contradictory or missing outputs (Error(Usage)/Error(Output)):
// called by renderScene first, and by the CLI before any work.
void checkRenderJob(const RenderJob& job);

// Renders; progress bars on stderr (unless quiet), and what happened along
// the way to job.events.
// Throws lattice::Error; the outputs are whole or absent.
RenderResult renderScene(const RenderJob& job);

}  // namespace lattice::app
