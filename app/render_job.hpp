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
#include "lht/leaf/lookup_mode.hpp"
#include "lht/table/lht_form.hpp"
#include "lht/table/lht_precision.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {

struct RenderJob {
  std::string scene;                  // scene file
  std::string device;                 // a device table name, or empty for a truecolour PNG
  std::vector<std::string> settings;  // the device profile's key=value overrides
  std::string picture;                // PNG to write: truecolour, or the emulator's screen; empty: none
  std::string stream;                 // the device's bytes to a file, or "-" for standard output
  std::optional<io::SerialOptions> port;  // ... or to a serial line
  bool baudFromProfile = false;       // the port's baud is the device profile's
  int width = 0;                      // 0: the scene's, fitted to the device's screen
  int height = 0;
  int threads = 0;                    // 0: all cores
  std::string arithmetic = "double";  // an arithmetic's name (foundation/arithmetics.hpp)
  bool fullRayTrace = false;          // lattices replaced by their exact CSG objects
  bool latticeShadows = true;
  std::optional<lht::LhtPrecision> precision;  // every lattice's entry precision
  std::optional<lht::LhtForm> form;            // every lattice's table form
  std::optional<lht::LatticeLookup> lookup;    // every lattice leaf's look-up
  bool lhtStats = false;                       // count and print the lattices' look-ups
  std::optional<std::uint64_t> onDemandCacheBytes;  // the on-demand form's bound
  std::optional<std::uint64_t> memoryBudget;   // bytes of peak resident memory
  bool modeChosenByUser = false;               // the quantizer mode is the user's (not the budget's)
  bool histogramChosenByUser = false;          // and the histogram form (--histogram)
  quantize::PipelineOptions pipeline;
  bool quiet = false;  // no progress bars
  RenderEvents events;  // told what happened along the way (app/render_events.hpp); empty: nobody
  double rdLambda = 0;               // rate-distortion runs (quantize/rate_distortion_runs.hpp); 0: lossless
  std::optional<WireBudget> wire;    // choose colours, dithering and lambda to fit (app/wire_budget.hpp)
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
