#pragma once
// What `lattice term` is asked to do: which terminal it is, where its bytes
// come from (a program on a pseudo-terminal, a serial line, or a recorded
// stream played at a line rate), and what it writes (a recording of every
// byte received, a PNG of the screen). The command line fills one of these
// (app/commands/cmd_term.cpp) and hands it to runTerm (term_session.hpp).
#include <string>
#include <vector>

#include "io/serial_options.hpp"

namespace lattice::app {

enum class TermSourceKind { Program, Port, Stream };

struct TermOptions {
  std::string device = "tek4125";
  std::vector<std::string> settings;  // the device profile's --set overrides
  TermSourceKind source = TermSourceKind::Program;
  std::vector<std::string> program;   // -- PROGRAM ARGS
  io::SerialOptions line;             // --port, --baud, --flow...
  bool baudGiven = false;             // else the device profile's rate plays a --stream
  std::string stream;                 // --stream FILE
  bool unpaced = false;               // --stream as fast as it decodes
  std::string snapshot;               // --snapshot FILE.png: at each refresh and at the end
  std::string record;                 // --record FILE: the exact bytes received
  double refreshPerSecond = 10;       // at most this many redraws (and snapshots) a second
  // The sixel display: Auto asks the host terminal; Off never draws (headless).
  enum class Display { Auto, Off } display = Display::Auto;
  std::string pngPrefix = "lattice-term";  // the PNG key writes PREFIX-N.png
};

}  // namespace lattice::app
