#pragma once
// The serial-line flags shared by `lattice send` and `lattice render --port`:
//
//   lattice::SerialOptions serial;
//   lattice::app::addSerialOptions(cmd, serial);
//   ... auto sink = lattice::openSerialSink(serial);   // io/serial_options.hpp
#include <CLI/CLI.hpp>

#include "io/serial_options.hpp"

namespace lattice::app {

// portRequired: `send` needs a port; `render` takes --port as one choice of output.
void addSerialOptions(CLI::App* cmd, io::SerialOptions& options, bool portRequired = true);

}  // namespace lattice::app
