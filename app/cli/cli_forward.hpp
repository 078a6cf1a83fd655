#pragma once
// CLI11's classes as the command-line headers name them, declared, not
// included. CLI11 2.1 (Debian 12) is header-only and every function of it is
// inline, so each object that includes <CLI/CLI.hpp> compiles the parts it
// calls again: that was half of `lattice`'s build time (docs/benchmarks.md,
// "Build time"). Headers take CLI::App by reference or pointer and include
// this; only the .cpp files that build or read a command tree include CLI11.

namespace CLI {
class App;
class ParseError;
}  // namespace CLI
