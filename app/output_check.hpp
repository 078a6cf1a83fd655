#pragma once
// An output path is checked before any work, so a long render never ends in
// "cannot write": its directory must exist and take a new file (probed by
// creating and removing one, which also catches read-only file systems and
// root-owned directories that permission bits alone would not), it must not
// be a directory, and an existing file without write permission is refused
// unless the user says --force (root could replace it, but a read-only file
// is usually read-only on purpose). "-" (standard output) passes.

#include <string>

// Declared, not included, as in app/cli/cli_forward.hpp (which this room may not include).
namespace CLI {
class App;
}  // namespace CLI

namespace lattice::app {

// Throws Error(Output) naming `flag`, the path and the fix.
void checkOutputPath(const std::string& path, const std::string& flag, bool force);

// For every command of `root` (nested ones too) with an -o/--output,
// --stream, --snapshot or --record option that writes (one checked with
// CLI::ExistingFile reads): adds --force and checks the paths given as soon as the
// command's flags are parsed, before its work starts. Reads the CLI11 tree,
// so a command added later is covered without being listed here.
void guardOutputs(CLI::App& root);

}  // namespace lattice::app
