#pragma once
// Everything about the Tektronix 4027 that the project had to assume lives
// here, in one place, with the reason. Confirmed facts (command character,
// separators, terminators, 8 paint pots, !MAP in HLS) come from the ncurses
// terminfo entries tek4024/4025/4027 and the ORNL COLORS.MEM note; the rest
// is marked "assumed" and can be overridden by a caller (`lattice` flags,
// tests). docs/tek4027.md explains each choice.
#include <string>
#include <string_view>
#include <vector>

#include "foundation/line_timing.hpp"

namespace lattice {

struct Tek4027Profile {
  // Command introducer; `!COM n` changes it on the terminal (n = ASCII code).
  char commandChar = '!';
  // Between arguments: a space or a comma (both legal on the terminal).
  char separator = ' ';
  // Ends the last command of a stream: CR or ';'. Between commands the
  // driver relies on the next command character, which also terminates.
  char terminator = '\r';

  // Graphics addressable area in pixels. Assumed 640x480 (not documented
  // anywhere we could find). Origin at the lower left, y up, as on other
  // Tektronix graphics terminals (assumed).
  int width = 640;
  int height = 480;

  // Text layout the set-up commands refer to. Assumed: a 34-line workspace,
  // the whole of it given to graphics (!WOR 34, !GRA 1,34), no monitor lines.
  int workspaceLines = 34;
  int graphicsFirstRow = 1;
  int graphicsLastRow = 34;

  // Line and terminal speed. The 4025 family draws about 400 characters a
  // second and needs XON/XOFF; 4800 baud 8N1 is the advised ceiling.
  LineFormat line{4800, 8, false, 1};
  double terminalCharsPerSecond = 400.0;

  // Paint pots on screen at once, and the pot that `!ERA G` clears to
  // (assumed C0, the pot of the power-up background).
  int colors = 8;
  int backgroundPot = 0;

  // Points the driver puts in one polyline command. The terminal's command
  // buffer limit is not known; 32 points keeps a command under ~260 chars.
  int maxPointsPerCommand = 32;

  // Throws lattice::Error(Usage) naming the bad field and its legal range.
  void validate() const;
};

// Apply one "key=value" from `--set` (keys: width, height, baud, data-bits,
// parity, stop-bits, chars-per-second, command-char (ASCII code), separator
// (space|comma), terminator (cr|semicolon), background-pot, max-points).
// Throws lattice::Error(Usage) and leaves the profile unchanged on a bad one.
void applyOverride(Tek4027Profile& profile, std::string_view keyValue);
void applyOverrides(Tek4027Profile& profile, const std::vector<std::string>& keyValues);
std::string describe(const Tek4027Profile& profile);

}  // namespace lattice
