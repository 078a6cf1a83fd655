#pragma once
// Where a picture for the terminal in front of the user goes by default: a
// device whose stream draws on that terminal (sixel: Device::showsOnTerminal)
// writes to standard output when no destination is named and standard output
// is a terminal. Progress bars are turned off then, because standard error
// is usually the same terminal and a bar's bytes inside the DCS string would
// be drawn as sixels.
#include "app/render_job.hpp"

namespace lattice::app {

// Fills job.stream with "-" (and quiets it) when the rule above applies.
void streamToTerminalByDefault(RenderJob& job);

}  // namespace lattice::app
