#pragma once
// The man page and the bash completion, generated from the CLI11 tree that
// `--help` prints, so neither can list a command or flag the program does
// not have (tests/app/help_export_test.cpp compares the page with --help).
// The build writes both with `lattice --generate-man FILE` and
// `lattice --generate-bash-completion FILE` (hidden flags, read before the
// command line is parsed) and `cmake --install` installs them.

#include <string>
#include <vector>

#include "app/cli/cli_forward.hpp"

namespace CLI {
class Option;
}  // namespace CLI

namespace lattice::app {

// The names a flag takes, where its check lists them (CLI11 writes an
// IsMember check into the type name, "TEXT:{a,b,c}"; the settings tables'
// choices reach it so): what completion offers and the CLI fuzzer tries.
std::vector<std::string> flagValueNames(const CLI::Option& option);

std::string manPage(const CLI::App& root, const std::string& version);
std::string bashCompletion(const CLI::App& root);

}  // namespace lattice::app
