#pragma once
// The flags of `lattice render` that fit a device's stream to the wire, read
// from the wire budget's schema (app/wire_budget_settings.hpp): --wire-seconds or
// --wire-bytes (a budget the search of app/wire_budget.hpp fits),
// --wire-quality (the floor of the size search, app/wire_size.hpp, which a
// budget runs unless --width/--height fix the size) and --wire-shrink. The
// budget's baud is --baud when given (the serial line's own), else the
// device profile's.

#include "app/cli/cli_forward.hpp"
#include "app/cli/setting_flags.hpp"
#include "app/render_job.hpp"

namespace lattice::app {

struct WireArgs {
  SettingFlagValues given;  // the flags' text, by key
};

void addWireOptions(CLI::App* cmd, WireArgs& args);
// Fills job.wire when a budget is given; `baud` is the serial flags' --baud.
// Flags that apply only to a budget, or that contradict the picture's size,
// are refused here.
void applyWireArgs(const WireArgs& args, const CLI::App& cmd, int baud, RenderJob& job);

}  // namespace lattice::app
