// `lattice term`: Lattice as a Tektronix 4125, 4027 or 4014 a person can
// use: run a program on a pseudo-terminal (`-- PROGRAM ARGS`), open a serial
// line (`--port PATH`), or play a recorded stream at a line rate
// (`--stream FILE`), and watch the picture arrive (docs/term.md). This file
// only reads flags; app/term/ is the terminal.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <vector>

#include "app/cli/number_flags.hpp"
#include "app/cli/serial_args.hpp"
#include "app/commands/commands.hpp"
#include "app/term/term_session.hpp"
#include "foundation/error.hpp"

namespace {

void runTermCommand(lattice::app::TermOptions o, const CLI::App& cmd, bool noDisplay) {
  using lattice::Error;
  using lattice::ErrorKind;
  using Kind = lattice::app::TermSourceKind;
  const bool port = cmd.count("--port") > 0, stream = cmd.count("--stream") > 0, program = !o.program.empty();
  if (int(port) + int(stream) + int(program) != 1)
    throw Error(ErrorKind::Usage,
                "term: give exactly one of -- PROGRAM [ARGS], --port PATH or --stream FILE (lattice term --help)");
  if (cmd.count("--unpaced") > 0 && !stream)
    throw Error(ErrorKind::Usage, "term: --unpaced plays a --stream; a program or a line sets its own pace");
  o.source = port ? Kind::Port : stream ? Kind::Stream : Kind::Program;
  o.baudGiven = cmd.count("--baud") > 0;
  if (noDisplay) o.display = lattice::app::TermOptions::Display::Off;
  // During the session standard error is the raw terminal: CR LF ends a line there.
  const bool rawHost = ::isatty(0) && ::isatty(2);
  const lattice::app::TermResult result = lattice::app::runTerm(
      o, [rawHost](const std::string& line) { fmt::print(stderr, "lattice term: {}{}", line, rawHost ? "\r\n" : "\n"); });
  fmt::print(stderr, "lattice term: {}; {} bytes received, {} answers sent", result.endReason, result.bytes,
             result.answers);
  if (result.displayed)
    fmt::print(stderr, "; {} redraws, {} sixel bytes (the last {}, a full frame {})", result.view.redraws,
               result.view.bytes, result.view.lastBytes, result.fullFrameBytes);
  fmt::print(stderr, "\n");
  for (const std::string& png : result.pngs) fmt::print(stderr, "lattice term: wrote {}\n", png);
  if (result.unknownCommands + result.malformed > 0)
    fmt::print(stderr, "lattice term: skipped {} unknown and {} malformed commands (lattice emulate --report on the "
               "--record lists them)\n", result.unknownCommands, result.malformed);
}

}  // namespace

namespace lattice::app {

void addTerm(CLI::App& root) {
  auto o = std::make_shared<TermOptions>();
  auto noDisplay = std::make_shared<bool>(false);
  auto* cmd = root.add_subcommand(
      "term", "Be a Tektronix 4125, 4027 or 4014: run a program, open a serial line or play a stream, and show "
              "its screen as it arrives (sixel)");
  cmd->add_option("--device", o->device, "The terminal to be: tek4125 (4100-series colour), tek4027 or tek4014")
      ->capture_default_str()
      ->check(CLI::IsMember({"tek4125", "tek4027", "tek4014"}));
  cmd->add_option("--set", o->settings, "Override a profile assumption, key=value (repeatable), e.g. --set planes=4");
  cmd->add_option("program", o->program, "After --: the program to run on the terminal, and its arguments");
  cmd->add_option("--stream", o->stream, "Play this recorded stream at the line rate (--baud, else the device's)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--unpaced", o->unpaced, "With --stream: play it as fast as the terminal decodes, not at a line rate");
  addSerialOptions(cmd, o->line, false, "the device profile's");
  // A terminal receives: the sender's stall time-out and pacing are not its business.
  for (const char* sendOnly : {"--stall-timeout", "--pace"}) cmd->remove_option(cmd->get_option(sendOnly));
  cmd->add_option("--snapshot", o->snapshot,
                  "PNG of the screen, rewritten (atomically) at each refresh and at the end");
  cmd->add_option("--record", o->record, "Save every byte received, as received: a stream for lattice emulate");
  cmd->add_option("--refresh", o->refreshPerSecond, "Redraw (and rewrite --snapshot) at most this many times a second")
      ->capture_default_str()
      ->check(numberIn({0.1, 60}));
  cmd->add_flag("--no-display", *noDisplay, "Do not draw in this terminal (headless; --snapshot keeps the screen)");
  cmd->add_option("--png-prefix", o->pngPrefix, "The PNG key (Ctrl-\\) writes PREFIX-N.png")->capture_default_str();
  cmd->footer(
      "Keys go to the program or line as typed; Ctrl-] quits and Ctrl-\\ writes a PNG of the screen. The screen\n"
      "is drawn as sixels where this terminal says it can (xterm -ti vt340, mlterm, foot, WezTerm); elsewhere\n"
      "lattice term says so and --snapshot keeps it. Examples:\n"
      "  lattice term --snapshot plot.png --record plot.tek -- gnuplot -e 'set term tek410x; plot sin(x)'\n"
      "  lattice term --port /dev/ttyUSB0 --baud 9600 --record session.tek\n"
      "  lattice term --stream plate6.tek --baud 38400\n"
      "docs/term.md has the whole manual.");
  cmd->callback([o, cmd, noDisplay] { runTermCommand(*o, *cmd, *noDisplay); });
}

}  // namespace lattice::app
