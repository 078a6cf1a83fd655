#pragma once
// The flags of `lattice render` that shape a device's stream for the wire:
// --rd-lambda (rate-distortion runs), --wire-seconds / --wire-bytes (a
// budget the search of app/wire_budget.hpp fits), --wire-shrink and
// --wire-quality (the floor of the size search, app/wire_size.hpp, which a
// budget runs unless --width/--height fix the size). The budget's baud is
// --baud when given (the serial flags' own), else the device profile's.

#include <string>

#include "app/cli/cli_forward.hpp"
#include "app/render_job.hpp"

namespace lattice::app {

struct WireArgs {
  double lambda = 0;
  double seconds = 0;
  std::string bytes;  // as typed: 57600, 56K
  bool shrink = false;
  double quality = 30;  // dB, the size search's floor
};

void addWireOptions(CLI::App* cmd, WireArgs& args);
// Fills job.rdLambda and job.wire; `baud` is the serial flags' --baud.
void applyWireArgs(const WireArgs& args, const CLI::App& cmd, int baud, RenderJob& job);

}  // namespace lattice::app
