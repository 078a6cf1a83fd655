#pragma once
// The `lattice` subcommands: one app/commands/cmd_<name>.cpp each, which defines the
// command's flags and calls one library function. main.cpp adds them from
// the one table below (no registration side effects), so the list of
// commands is read in one place. A callback reports failure by throwing
// lattice::Error (foundation/error.hpp); the error's kind is the exit code.

#include "app/cli/cli_forward.hpp"

namespace lattice::app {

void addBake(CLI::App& root);
void addDiff(CLI::App& root);
void addEmulate(CLI::App& root);
void addExport(CLI::App& root);
void addLhtInfo(CLI::App& root);
void addPorts(CLI::App& root);
void addQuantize(CLI::App& root);
void addRasterize(CLI::App& root);
void addRender(CLI::App& root);
void addSend(CLI::App& root);
void addShow(CLI::App& root);
void addTable1(CLI::App& root);
void addTerm(CLI::App& root);

using CommandAdder = void (*)(CLI::App& root);

// In the order `lattice --help` lists them.
inline constexpr CommandAdder kCommands[] = {addBake,     addDiff,   addEmulate, addExport, addLhtInfo, addPorts,
                                             addQuantize, addRasterize, addRender, addSend, addShow, addTable1,
                                             addTerm};

}  // namespace lattice::app
