#pragma once
// How the emulator reads what no public source settles about a 4100-series
// terminal (docs/tek4125.md, "Readings"). A strict stream must draw the same
// picture under every reading, which the tests prove by decoding it under
// each (tests/support/tek4125_readings.hpp spells them as key=value). They
// are not user settings: the driver ignores them, and a user with a real
// terminal has nothing to set; the defaults are the readings the sources
// lean to.
namespace lattice::tek4125 {

// The colour map a terminal shows before any TG: two public tables disagree
// on entries 5..7 (PGPLOT drivers/tkdriv.f: 5 cyan, 6 magenta, 7 yellow;
// RAL-CGM cgmtek.h: 5 yellow, 6 cyan, 7 magenta).
enum class Tek4125PowerUpMap { Pgplot, RalCgm };

struct Tek4125Readings {
  Tek4125PowerUpMap powerUpMap = Tek4125PowerUpMap::Pgplot;
  bool rrFromViewport = false;  // RR corners relative to the pixel viewport, not the screen
  bool rhFromScreen = false;    // RH relative to the screen, not the viewport
  int surfacePlanes = 0;        // planes of surface 1 before any RD (0 = all; more than the profile's: all)
  // RP and RL pack pixels by surface 1's planes instead of the bits RU set
  // (no source writes fewer bits than its surface has).
  bool pixelBitsFromSurface = false;
  // After RS the beam starts at the viewport's upper-left corner, wrapping
  // a row down, instead of the lower-left wrapping up (what the RAL GKS
  // driver's bottom-row-first RL rasters need).
  bool rasterRowsDown = false;
};

}  // namespace lattice::tek4125
