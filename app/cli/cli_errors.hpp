#pragma once
// One form for every command-line mistake: `lattice: error: WHAT; FIX`, CLI11's
// own parse errors included. The known names are read from the parsed CLI11
// tree itself (its subcommands and their options), so a command or flag
// added anywhere is suggested without a list to keep up to date.

#include <string>
#include <vector>

#include "app/cli/cli_forward.hpp"

namespace lattice::app {

// The message (without the `lattice: error: ` prefix) for a parse error of
// `root` on the command line `arguments` (argv without the program name).
std::string describeParseError(const CLI::App& root, const CLI::ParseError& error,
                               const std::vector<std::string>& arguments);

// Every long and short flag of a command, as typed ("--width", "-o"), in help order.
std::vector<std::string> flagNames(const CLI::App& command);
// The subcommands of `root`, in help order.
std::vector<std::string> commandNames(const CLI::App& root);

}  // namespace lattice::app
