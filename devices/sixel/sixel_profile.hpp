#pragma once
// What the sixel driver assumes of its terminal, with the reason for each
// default; `--set key=value` overrides any of them (docs/sixel.md).
#include <string>
#include <string_view>
#include <vector>

#include "foundation/settings_schema.hpp"

namespace lattice::sixel {

struct SixelProfile {
  // Colour registers: 16 on a VT340 and on xterm's `-ti vt340` by default;
  // xterm takes up to 1024 with its numColorRegisters resource (256 is the
  // most a Lattice palette uses).
  int registers = 16;
  // The largest picture: xterm's maxGraphicSize resource defaults to
  // 1000x1000 and refuses a raster larger than it.
  int width = 1000;
  int height = 1000;
  // DCS parameters. P1 selects the pixel aspect (the raster attributes' 1:1
  // override it in xterm and the VT340, so 0 is kept). P2 = 1 leaves pixels
  // no sixel writes as they were; 0 (the default) fills the raster with
  // register 0 first in xterm. Lattice writes every pixel, so both show the
  // same picture. Parameters equal to the defaults (0) are left out.
  int p1 = 0;
  int p2 = 0;

  // Throws lattice::Error(Usage) naming the bad field and its range.
  void validate() const;
};

// The profile's settings, each key declared once (sixel_profile.cpp):
// --set, describe() and docs/cli.md's table are read from it.
const SettingsSchema<SixelProfile>& sixelSettings();

// One "key=value" from `--set`. Throws lattice::Error(Usage) naming the key
// and what it takes (or listing the keys), and leaves the profile unchanged
// on a bad one.
void applyOverride(SixelProfile& profile, std::string_view keyValue);
void applyOverrides(SixelProfile& profile, const std::vector<std::string>& keyValues);
std::string describe(const SixelProfile& profile);

}  // namespace lattice::sixel
