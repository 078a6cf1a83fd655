#pragma once
// Everything Lattice assumes about a Tektronix 4125, in one place. The
// values no public source confirms are marked "assumed" (docs/tek4125.md
// gives the reasoning); each can be overridden from the command line with
// "key=value" (applyOverride), so a user with a real terminal can correct us.
#include <string>
#include <string_view>
#include <vector>

#include "devices/tek4125/tek4125_forms.hpp"
#include "devices/tek4125/tek4125_strategy.hpp"
#include "foundation/line_timing.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::tek4125 {

struct Tek4125Profile {
  int width = 1280;          // visible pixels (assumed, as the sibling 4115B)
  int height = 1024;
  int planes = 8;            // bit planes: 4 or 8 (assumed 8; "planes=4" for a 16-colour unit)
  int paletteBits = 24;      // colour map precision: 8 bits a gun, loaded as 0..100 percent
  int reserved = 0;          // colour map entries left alone (e.g. for dialog-area text)
  int baud = 38400;          // the fastest standard rate of the 4100 family's host port (assumed)
  int dataBits = 8;
  bool parity = false;
  int stopBits = 1;
  bool xonXoff = true;       // DC1/DC3 flagging, the usual setting at these rates
  std::string forms = "strict";  // the form set the driver may use (tek4125_forms.hpp)
  std::string strategy = "shortest";  // how the driver chooses among those forms (tek4125_strategy.hpp)
  bool progressive = false;  // progressive=on: covers, then draft rows, then exact rows (tek4125_progressive.hpp)
  // xy-short=on: in a five-byte-xy form set (strict), an RR or RH xy after
  // another leaves out an unchanged Hi-Y and Hi-X, as OpenVnmrJ's tek_coord0
  // does (one source; off by default, so strict's default bytes stay).
  bool xyShort = false;
  // ru-bits=fit: in a form set that allows it (compact), RU writes as few
  // bits a pixel as the palette needs (no source: off by default, so the
  // default streams stay; a wire budget turns it on). planes: the planes.
  bool ruBitsFit = false;
  // (How the emulator reads what no source settles is not a setting:
  // tek4125_readings.hpp.)

  int colorMapSize() const { return 1 << planes; }
  // Colours a picture may use: the map minus reserved entries.
  int maxColors() const { return colorMapSize() - reserved; }
  // Bits a pixel the driver writes for a picture of `colours` colours: 4 when
  // they fit in 16 entries (the one depth a source packs RP at), else the
  // planes, or with ru-bits=fit where the form set allows it the fewest that
  // hold them.
  int pixelBitsFor(int colours) const;
  LineFormat line() const { return LineFormat{baud, dataBits, parity, stopBits}; }
  const Tek4125Forms& formSet() const { return tek4125Forms(forms); }
  // Throws lattice::Error(Usage) naming the bad field and its legal range.
  void validate() const;
};

// The profile's settings, each key declared once (tek4125_profile.cpp):
// --set, describe() and docs/cli.md's table are read from it.
const SettingsSchema<Tek4125Profile>& tek4125Settings();

// Apply one "key=value". Unknown keys and bad values throw
// lattice::Error(Usage) naming the key and what it takes (or listing the
// keys), and leave the profile as it was.
void applyOverride(Tek4125Profile& profile, std::string_view keyValue);
void applyOverrides(Tek4125Profile& profile, const std::vector<std::string>& keyValues);
// One key=value line per setting, in the table's order: what --set takes back.
std::string describe(const Tek4125Profile& profile);

}  // namespace lattice::tek4125
