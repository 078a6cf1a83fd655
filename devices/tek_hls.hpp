#pragma once
// Hue, lightness and saturation as Tektronix and DEC define colours: the 4027
// defines paint pots this way, and a sixel colour register may be given so
// (`#i;1;h;l;s`, docs/sixel-sources.md). We assume the Tektronix HLS convention
// (the one the 4100 series documents, and DEC's for the VT340): hue in degrees
// 0..359 with BLUE at 0, red at 120, green at 240; lightness and saturation in
// percent 0..100. It is the textbook HLS double hexcone (Foley & van Dam) with
// the hue wheel turned by 120 degrees.
//
// RGB -> HLS is computed in double precision and each component rounded to
// the nearest integer (hue modulo 360), because the terminal takes integers.
// HLS -> RGB (the emulator, and what the terminal would show) rounds each gun
// to the nearest of 0..255. The round trip is therefore not exact; the bound
// is measured in tests/devices/tek4027/hls_test.cpp and given in docs/tek4027.md.
#include "foundation/scanline.hpp"

namespace lattice::devices {

struct Hls {
  int hue = 0;         // 0..359, blue = 0
  int lightness = 0;   // 0..100
  int saturation = 0;  // 0..100
  friend bool operator==(const Hls&, const Hls&) = default;
};

Hls rgbToTekHls(Rgb8 rgb);
// hue is taken modulo 360 (negative too); lightness and saturation are
// clamped to 0..100.
Rgb8 tekHlsToRgb(Hls hls);

// Largest per-channel difference of the round trip rgb -> HLS -> rgb that
// tests guarantee over the whole 8-bit cube.
constexpr int kHlsRoundTripMaxDelta = 5;

}  // namespace lattice::devices
