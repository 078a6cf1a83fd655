// The `lattice` command: everything it does is app/commands/run_lattice.hpp,
// which the command-line fuzzer calls too. Subcommands live in
// app/commands/cmd_*.cpp; exit codes are documented in docs/cli.md and
// defined by lattice::ErrorKind. The heap keeps its large blocks for reuse
// (foundation/system/heap_reuse.hpp): a render's set-up frees and allocates
// megabytes, and pages reused are pages not faulted in again.
#include "app/commands/run_lattice.hpp"
#include "foundation/system/heap_reuse.hpp"

int main(int argc, char** argv) {
  lattice::keepLargeBlocksInHeap();
  return lattice::app::runLattice(argc, argv);
}
