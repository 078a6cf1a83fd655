#pragma once
// A benchmark program's main: runs its body, and turns an error into a line
// on stderr named for the program and the exit code the `lattice` command
// would give (lattice::Error's kind; 70 for anything else), so the scripts
// that run the benchmarks stop with a reason.
#include <cstdio>
#include <exception>

#include "foundation/error.hpp"

namespace lattice::bench {

template <typename Body>
int runBenchMain(const char* name, Body body) {
  try {
    return body();
  } catch (const lattice::Error& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return e.exitCode();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 70;
  }
}

}  // namespace lattice::bench
