#pragma once
// Sending a stored command stream to a terminal over a serial line or a
// virtual terminal (`--port virtual:DEVICE`): the body of `lattice send`,
// and the second half of `lattice render --port`, which records the stream
// to a file first so that a send that stops can be resumed. Prints its
// progress and, when the send stops, the `--resume` command that continues
// it; a signal that stopped it ends the process by that signal.
#include <cstdint>
#include <string>
#include <vector>

#include "io/serial_options.hpp"

namespace lattice::app {

struct SendArgs {
  std::string stream;
  std::string device;                 // empty: send without waiting for answers
  std::vector<std::string> settings;  // the device profile's --set overrides
  io::SerialOptions serial;
  bool baudGiven = false;             // --baud given; else a virtual terminal takes its profile's rate
  std::uint64_t resume = 0;
  std::string screen;        // with a virtual terminal: the PNG of what it drew
  bool screenGiven = false;  // -o given (a real terminal's screen cannot be read back)
  bool force = false;        // --force: the screen may replace a read-only file
  bool raw = false;          // send even what does not look like a terminal stream
  std::string who = "lattice send";  // how messages name the command
};

void runSend(const SendArgs& args);

}  // namespace lattice::app
