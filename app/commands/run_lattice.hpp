#pragma once
// The whole `lattice` program as one call, so the executable's main() and the
// command-line fuzzer (fuzz/cli_entry.cpp) run exactly the same code: the
// command table, the guards every command gets (output paths, numbers), the
// parse, the command, its outputs committed as one transaction, and the
// mapping of errors to exit codes (docs/cli.md).
#include "app/cli/cli_forward.hpp"

namespace lattice::app {

// Adds every command of kCommands to `root` with the guards main() gives them.
void buildCommandTree(CLI::App& root);

// argv as main() receives it; returns the exit code. Writes to stdout/stderr.
int runLattice(int argc, char** argv);

}  // namespace lattice::app
