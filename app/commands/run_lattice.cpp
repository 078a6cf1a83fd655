#include "app/commands/run_lattice.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <cstdint>
#include <new>
#include <span>
#include <string_view>
#include <string>
#include <vector>

#include "app/cli/cli_errors.hpp"
#include "app/commands/commands.hpp"
#include "app/cli/help_export.hpp"
#include "app/cli/number_flags.hpp"
#include "app/output_check.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/system/output_transaction.hpp"
#include "foundation/error.hpp"

namespace lattice::app {
namespace {

// A progress line may have said "-> x.tek" before the command failed: say
// that it did not land, and that the file that was there is as it was.
void sayDiscarded(const OutputTransaction& outputs) {
  const std::vector<std::filesystem::path> targets = outputs.pendingTargets();
  if (targets.empty()) return;
  std::string names;
  for (const std::filesystem::path& target : targets) names += (names.empty() ? "" : ", ") + target.string();
  fmt::print(stderr, "lattice: not written, as the command failed: {} (any file there before is unchanged)\n", names);
}

// A repeatable flag (--set a=1 --set b=2) takes one value each time it is
// given, so `emulate --set bits=12 S.tek` leaves S.tek to the positional
// argument instead of reading it as a second setting (CLI11's default for a
// vector-valued flag is every word up to the next flag).
void oneValueAnOccurrence(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    oneValueAnOccurrence(*command);
    for (CLI::Option* option : command->get_options())
      if (option->nonpositional()) option->allow_extra_args(false);
  }
}

}  // namespace

void buildCommandTree(CLI::App& root) {
  root.set_version_flag("--version", LATTICE_VERSION);
  root.require_subcommand(1);
  root.footer("Run `lattice COMMAND --help` for a command's options. Exit codes: docs/cli.md.");
  for (auto adder : kCommands) adder(root);
  guardOutputs(root);
  guardNumbers(root);
  oneValueAnOccurrence(root);
}

int runLattice(int argc, char** argv) {
  // Named here, so usage lines say `lattice`, not the path it was run by.
  CLI::App root{"lattice: three-dimensional texturing using lattices (Lewis 1988), rendered to\n"
                "PNG, Tektronix 4125/4027 command streams and a simulated Apollo DN660.",
                "lattice"};
  buildCommandTree(root);
  // The build's man page and completion (app/cli/help_export.hpp); hidden flags.
  if (argc == 3 && (std::string_view(argv[1]) == "--generate-man" ||
                    std::string_view(argv[1]) == "--generate-bash-completion")) {
    try {
      const std::string text = std::string_view(argv[1]) == "--generate-man"
                                   ? manPage(root, LATTICE_VERSION)
                                   : bashCompletion(root);
      writeFileAtomically(argv[2], std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
      return 0;
    } catch (const Error& e) {
      fmt::print(stderr, "lattice: error: {}\n", e.what());
      return e.exitCode();
    }
  }

  // A command's outputs land together or not at all (foundation/system/output_transaction.hpp).
  OutputTransaction outputs;
  try {
    root.parse(argc, argv);
    outputs.commit();
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return root.exit(e);  // --help, --version
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    fmt::print(stderr, "lattice: error: {}\n", describeParseError(root, e, arguments));
    return static_cast<int>(ErrorKind::Usage);
  } catch (const Error& e) {
    std::fflush(stdout);
    fmt::print(stderr, "lattice: error: {}\n", e.what());
    if (e.keepsOutputs()) {
      try {
        outputs.commit();
      } catch (const Error& failed) {
        fmt::print(stderr, "lattice: error: {}\n", failed.what());
        return failed.exitCode();
      }
    } else {
      sayDiscarded(outputs);
    }
    return e.exitCode();
  } catch (const std::bad_alloc&) {
    // Memory runs out when an input asks for more than the machine (or a
    // ulimit) gives: a property of the input, so exit 3, not a bug (70).
    std::fflush(stdout);
    fmt::print(stderr,
               "lattice: error: out of memory: the input asks for more memory than is available (limits: "
               "docs/limits.md; a smaller --width/--height or count, or more memory, may help)\n");
    sayDiscarded(outputs);
    return static_cast<int>(ErrorKind::Input);
  } catch (const std::exception& e) {
    std::fflush(stdout);
    fmt::print(stderr, "lattice: internal error: {}\n(please report this with the command line that caused it)\n", e.what());
    return static_cast<int>(ErrorKind::Internal);
  }
  return 0;
}

}  // namespace lattice::app
