// The `lattice` command. Subcommands live in app/cmd_*.cpp; exit codes are
// documented in docs/cli.md and defined by lattice::ErrorKind.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>

#include "app/commands.hpp"
#include "foundation/error.hpp"

int main(int argc, char** argv) {
  CLI::App root{"lattice: three-dimensional texturing using lattices (Lewis 1988), rendered to\n"
                "PNG, Tektronix 4125/4027 command streams and a simulated Apollo DN660."};
  root.set_version_flag("--version", LATTICE_VERSION);
  root.require_subcommand(1);
  root.footer("Run `lattice COMMAND --help` for a command's options. Exit codes: docs/cli.md.");
  for (auto adder : lattice::app::kCommands) adder(root);

  try {
    root.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = root.exit(e);  // prints help/version (code 0) or the parse error
    return code == 0 ? 0 : static_cast<int>(lattice::ErrorKind::Usage);
  } catch (const lattice::Error& e) {
    std::fflush(stdout);
    fmt::print(stderr, "lattice: error: {}\n", e.what());
    return e.exitCode();
  } catch (const std::bad_alloc&) {
    // Memory runs out when an input asks for more than the machine (or a
    // ulimit) gives: a property of the input, so exit 3, not a bug (70).
    std::fflush(stdout);
    fmt::print(stderr,
               "lattice: error: out of memory: the input asks for more memory than is available (limits: "
               "docs/limits.md; a smaller --width/--height or count, or more memory, may help)\n");
    return static_cast<int>(lattice::ErrorKind::Input);
  } catch (const std::exception& e) {
    std::fflush(stdout);
    fmt::print(stderr, "lattice: internal error: {}\n(please report this with the command line that caused it)\n", e.what());
    return static_cast<int>(lattice::ErrorKind::Internal);
  }
  return 0;
}
