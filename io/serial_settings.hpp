#pragma once
// A serial line's settings, each declared once: rate, flow control,
// character format, how long a held line is waited for, and pacing. The
// line flags of `send`, `term` and `render --port`, their help and
// docs/cli.md's table are read from this table, and SerialOptions::validate
// checks a line built in code against the same rows. The port is where the
// line goes, not how it runs, and has no row.
#include "foundation/settings_schema.hpp"
#include "io/serial_options.hpp"

namespace lattice::io {

const SettingsSchema<SerialOptions>& serialSettings();

}  // namespace lattice::io
