#pragma once
// Running the real `lattice` binary from a test, as a user would: command-line
// tests check exit codes and messages end to end. LATTICE_EXE overrides the
// binary (e.g. one built elsewhere); by default it is the build tree's.
#include <filesystem>
#include <string>

namespace lattice::testing {

std::filesystem::path latticeBinary();

struct CommandRun {
  int exitCode = -1;  // -1 when the process did not exit normally
  std::string stderrText;
};

// Runs `lattice ARGUMENTS` through the shell with stdin from /dev/null.
CommandRun runLattice(const std::string& arguments);

}  // namespace lattice::testing
