#pragma once
// What the project assumes about a Tektronix 4014 (and xterm's Tek window,
// `xterm -t`, which emulates one), in one place. docs/tek4014.md explains each
// choice; docs/tek4014-sources.md cites the byte forms.
//
// Method and tunables:
//  - Addressing: 10 bits (1024x780, every 4010-series terminal) or 12 bits
//    (4096x3120, the 4014's enhanced graphics module: one "extra" byte per
//    address carries the two low bits of x and y). One picture pixel is one
//    address unit, so the screen is 1024x780 or 4096x3120 pixels.
//  - Dither: the picture's luminance is dithered to lit and dark dots:
//    Floyd-Steinberg error diffusion (default), an 8x8 Bayer matrix, or a
//    plain threshold at half luminance.
//  - Line: 9600 baud 8N1 (the fastest rate the 4014's interface offers; only
//    the reported transmit time depends on it).
#include <string>
#include <string_view>
#include <vector>

#include "foundation/line_timing.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::tek4014 {

enum class Tek4014Dither { FloydSteinberg, Ordered, Threshold };

struct Tek4014Profile {
  int addressBits = 10;  // 10 or 12
  Tek4014Dither dither = Tek4014Dither::FloydSteinberg;
  LineFormat line{9600, 8, false, 1};

  // The screen in address units (= pixels): 1024x780 or 4096x3120.
  int width() const { return addressBits == 12 ? 4096 : 1024; }
  int height() const { return addressBits == 12 ? 3120 : 780; }
  // Bits an address unit is shifted left to make the 12-bit coordinate every
  // stream byte is decoded into (xterm keeps 12 bits whatever is sent).
  int shift() const { return addressBits == 12 ? 0 : 2; }
};

std::string_view ditherName(Tek4014Dither dither);

// The profile's settings, each key declared once (tek4014_profile.cpp):
// --set, describe() and docs/cli.md's table are read from it.
const SettingsSchema<Tek4014Profile>& tek4014Settings();

// One "key=value" from `--set`. Throws lattice::Error(Usage) naming the key
// and what it takes (or listing the keys), and leaves the profile unchanged
// on a bad one.
void applyOverride(Tek4014Profile& profile, std::string_view keyValue);
void applyOverrides(Tek4014Profile& profile, const std::vector<std::string>& keyValues);
std::string describe(const Tek4014Profile& profile);

}  // namespace lattice::tek4014
