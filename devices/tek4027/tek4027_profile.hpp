#pragma once
// Everything about the Tektronix 4027 that the project had to assume lives
// here, in one place, with the reason. Two named profiles are data in
// tek4027_profile.cpp: `strict` (the default) permits only command forms that
// at least one independent source shows (docs/tek-sources.md, "Tek 4027");
// `compact` keeps the older, shorter but unsourced forms (!MAP in HLS, a
// 34-line workspace, 640x480). Any field can be overridden by a caller
// (`lattice --set`, tests). docs/tek4027.md explains each choice.
#include <string>
#include <string_view>
#include <vector>

#include "foundation/line_timing.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::tek4027 {

// How a paint pot's colour is defined. Mix: `!MIX Cn r,g,b`, RGB percent
// (sourced). Map: `!MAP Cn h l s`, Tektronix HLS (no source found).
enum class Tek4027ColourForm { Mix, Map };

// Whether the stream asks the terminal to report after each record
// (`!REP 00`) so a sender can wait for the answer before the next record.
// Auto: only when the stream is longer than one record.
enum class Tek4027Pacing { None, Report, Auto };

struct Tek4027Profile {
  // The preset this profile started from ("strict" or "compact").
  std::string name = "strict";
  // Command introducer; `!COM n` changes it on the terminal (n = ASCII code).
  char commandChar = '!';
  // Between arguments: a space or a comma (both legal on the terminal).
  char separator = ' ';
  // Ends the last command of a stream: CR or ';'. Between commands the
  // driver relies on the next command character, which also terminates.
  char terminator = '\r';

  // Graphics addressable area in pixels, origin at the lower left, y up.
  // Strict: 640x350, the size the UGS manual gives for its default 26-line
  // graphics area; compact: 640x480 (unsourced).
  int width = 640;
  int height = 350;

  // Text layout the set-up commands refer to: `!WOR n` workspace lines, then
  // `!GRA first last` graphics rows. Strict: 26 and 1..26 (UGS's default
  // DLINES; UGS allows at most 33). Compact: 34 and 1..34 (unsourced).
  int workspaceLines = 26;
  int graphicsFirstRow = 1;
  int graphicsLastRow = 26;

  // Forms the encoder may use (one place decides: the presets below).
  Tek4027ColourForm colourForm = Tek4027ColourForm::Mix;
  bool relativeVectors = true;  // `!RVE dx,dy...` (one source)
  Tek4027Pacing pacing = Tek4027Pacing::Auto;
  // Bytes of one record before its `!REP 00` request: UGS's own output
  // buffer for this terminal holds 504 characters.
  int recordBytes = 504;

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

  // The emulator's reading of `!RVE`'s first pair (the driver ignores it):
  // a relative move, as in `!VEC` and as the font tool's use reads
  // (`rve-first=move`), or the first drawn step (`rve-first=draw`).
  bool rveFirstMoves = true;

  // Throws lattice::Error(Usage) naming the bad field and its legal range.
  void validate() const;
};

// The named presets: "strict" (default) and "compact". Throws
// lattice::Error(Usage) naming the choices for any other name.
Tek4027Profile tek4027Preset(std::string_view name);
std::vector<std::string> tek4027PresetNames();

// The profile's settings, each key declared once (tek4027_profile.cpp):
// --set, describe() and docs/cli.md's table are read from it.
const SettingsSchema<Tek4027Profile>& tek4027Settings();

// Apply one "key=value" from `--set`. Throws lattice::Error(Usage) naming the
// key and what it takes (or listing the keys), and leaves the profile
// unchanged on a bad one. applyOverrides() applies `profile=` (a preset)
// first, so the other keys refine it.
void applyOverride(Tek4027Profile& profile, std::string_view keyValue);
void applyOverrides(Tek4027Profile& profile, const std::vector<std::string>& keyValues);
std::string describe(const Tek4027Profile& profile);

}  // namespace lattice::tek4027
