// The `lattice` command: everything it does is app/commands/run_lattice.hpp,
// which the command-line fuzzer calls too. Subcommands live in
// app/commands/cmd_*.cpp; exit codes are documented in docs/cli.md and
// defined by lattice::ErrorKind.
#include "app/commands/run_lattice.hpp"

int main(int argc, char** argv) { return lattice::app::runLattice(argc, argv); }
