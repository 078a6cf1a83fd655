#pragma once
// The serial-line flags shared by `lattice send` and `lattice render --port`:
//
//   lattice::SerialOptions serial;
//   lattice::app::addSerialOptions(cmd, serial);
//   ... auto sink = lattice::openSerialSink(serial);   // io/serial_options.hpp

#include <string>

#include "app/cli/cli_forward.hpp"
#include "io/serial_options.hpp"

namespace lattice::app {

// portRequired: `send` needs a port; `render` takes --port as one choice of output.
// baudDefault: what --baud's help gives as its default when that is not the
// options' own (render's is the device profile's); empty: options.baud.
// The flags are listed under the help group "Serial line".
void addSerialOptions(CLI::App* cmd, io::SerialOptions& options, bool portRequired = true,
                      const std::string& baudDefault = "");

}  // namespace lattice::app
