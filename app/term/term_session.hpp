#pragma once
// `lattice term`: Lattice as the terminal. Bytes come from a program on a
// pseudo-terminal, a serial line or a recorded stream (term_source.hpp);
// each piece goes to the screen (term_screen.hpp: record, emulator,
// answers); the user's keys go back (term_keys.hpp); the screen is shown in
// the user's own terminal as sixels where it can show them
// (host_graphics.hpp, sixel_view.hpp) and written as a PNG.
//
// Method: one thread and one poll() over the source's descriptor and the
// keyboard, with a timeout only while something is due (a paced stream's
// next slice, a redraw held back by the refresh rate): an idle terminal
// sleeps in poll and costs nothing. Redraws (and --snapshot rewrites) happen
// at most refreshPerSecond times a second and only when bytes arrived since
// the last one, so a fast line costs one redraw per interval however many
// pieces it brings. SIGINT, SIGTERM and SIGHUP end the session like the
// quit key (io/stream_sender.hpp's SendSignals records them), so the host
// terminal is restored and the recording and snapshot are written.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/term/sixel_view.hpp"
#include "app/term/term_options.hpp"

namespace lattice::app {

struct TermResult {
  std::string endReason;        // "gnuplot exited with status 0", "the quit key", ...
  std::uint64_t bytes = 0;      // received
  std::uint64_t answers = 0;    // requests answered
  std::uint64_t refreshes = 0;  // redraws and snapshots made
  bool displayed = false;       // sixels were drawn in the host terminal
  ViewStats view;               // the sixel display's bytes
  std::uint64_t fullFrameBytes = 0;  // one full frame of the final screen, for comparison
  std::vector<std::string> pngs;     // written by the PNG key
  std::uint64_t unknownCommands = 0, malformed = 0;
};

// Says a line to the user (the command prints it on standard error, after
// the host terminal is back in its own mode when the session is over).
using TermSay = std::function<void(const std::string&)>;

TermResult runTerm(const TermOptions& options, const TermSay& say);

}  // namespace lattice::app
