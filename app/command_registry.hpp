#pragma once
// Subcommands register themselves, so adding one touches one file:
//
//   // app/cmd_ports.cpp
//   static void addPorts(CLI::App& root) {
//     auto* cmd = root.add_subcommand("ports", "List serial ports");
//     cmd->callback([=] { ... });   // throw lattice::Error on failure
//   }
//   LATTICE_COMMAND(addPorts);
//
// A callback reports failure by throwing lattice::Error (util/error.hpp); the
// error's kind becomes the exit code. Success is exit 0.
#include <CLI/CLI.hpp>

#include <functional>
#include <vector>

namespace lattice::app {

using CommandAdder = void (*)(CLI::App& root);

std::vector<CommandAdder>& commandAdders();

struct CommandRegistration {
  explicit CommandRegistration(CommandAdder adder) { commandAdders().push_back(adder); }
};

}  // namespace lattice::app

#define LATTICE_COMMAND(adder) \
  static const ::lattice::app::CommandRegistration latticeCommandRegistration_##adder{adder}
