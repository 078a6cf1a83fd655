#pragma once
// The user's keys: every key goes to the program or line as typed, except
// two that the terminal keeps for itself, chosen from the control keys a
// graphics program is least likely to want from a keyboard and that telnet
// and ssh users already know as "leave": Ctrl-] (GS) quits, Ctrl-\ (FS)
// writes a PNG of the screen. In raw mode neither raises a signal.
#include <cstdint>
#include <span>
#include <vector>

namespace lattice::app {

inline constexpr std::uint8_t kQuitKey = 0x1d;  // Ctrl-]
inline constexpr std::uint8_t kPngKey = 0x1c;   // Ctrl-backslash

struct KeyActions {
  std::vector<std::uint8_t> forward;  // for the program or line, in order
  int pngs = 0;                       // PNG key presses
  bool quit = false;                  // the quit key (keys after it are dropped)
};

KeyActions readKeys(std::span<const std::uint8_t> keys);

}  // namespace lattice::app
