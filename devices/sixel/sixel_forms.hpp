#pragma once
// The byte forms of DEC sixel graphics that the driver writes and the
// emulator reads, in one place. Sources for each (DEC's VT330/VT340
// Programmer Reference, chapter 14 "Sixel Graphics", and xterm's
// graphics_sixel.c) are in docs/sixel-sources.md.
//
//   ESC P P1;P2;P3 q   DCS: start sixel mode; P1 aspect selector, P2 background
//                      mode (1: unwritten pixels keep their colour), P3 grid (ignored)
//   " Pan;Pad;Ph;Pv    DECGRA raster attributes: pixel aspect Pan:Pad, size Ph x Pv
//   # Pc;Pu;Px;Py;Pz   DECGCI: define register Pc (Pu 1 = HLS, 2 = RGB percent)
//   # Pc               DECGCI: select register Pc for the sixels that follow
//   ! Pn c             DECGRI: sixel c repeated Pn times
//   $                  DECGCR: graphics carriage return (back to column 0 of the band)
//   -                  DECGNL: graphics new line (next band, six rows down, column 0)
//   ? .. ~             a sixel: byte - 0x3F, bit 0 the top row of the band
//   ESC \              ST: leave sixel mode
#include <cstdint>
#include <string_view>

namespace lattice::sixel {

inline constexpr std::uint8_t kEsc = 0x1B;
inline constexpr std::string_view kDcs = "\x1bP";   // 7-bit DCS
inline constexpr std::string_view kSt = "\x1b\\";   // 7-bit ST
inline constexpr std::uint8_t kDcs8 = 0x90;         // 8-bit DCS, read only
inline constexpr std::uint8_t kSt8 = 0x9C;          // 8-bit ST, read only
inline constexpr char kSixelFinal = 'q';
inline constexpr char kRaster = '"';
inline constexpr char kColour = '#';
inline constexpr char kRepeat = '!';
inline constexpr char kCarriageReturn = '$';
inline constexpr char kNewLine = '-';
inline constexpr std::uint8_t kSixelFirst = 0x3F;  // '?', no bit set
inline constexpr std::uint8_t kSixelLast = 0x7E;   // '~', all six bits
inline constexpr int kBandRows = 6;
inline constexpr int kColourSpaceHls = 1;
inline constexpr int kColourSpaceRgb = 2;


}  // namespace lattice::sixel
