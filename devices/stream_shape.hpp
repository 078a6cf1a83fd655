#pragma once
// Shapes of the terminals' byte streams that several devices' recognisers
// (Device::recognise) share.
//
// Method and tunables: the Tektronix terminals take 7-bit ASCII, so a stream
// for them has (almost) no byte at or above 0x80, where a PNG, a JPEG or any
// compressed file has about half its bytes. kMaxEightBitShare allows 1 % (a
// stray byte from a line with parity, or a comment in a gnuplot stream)
// while refusing every binary file format.
#include <cstdint>
#include <span>

namespace lattice::devices {

inline constexpr double kMaxEightBitShare = 0.01;

inline bool mostlySevenBit(std::span<const std::uint8_t> bytes) {
  std::size_t high = 0;
  for (std::uint8_t b : bytes) high += b >= 0x80 ? 1 : 0;
  return static_cast<double>(high) <= kMaxEightBitShare * static_cast<double>(bytes.size());
}

// A sixel picture's introducer: DCS (ESC P, or the 8-bit 0x90), then only
// parameters (digits and `;`), then `q` (docs/sixel-sources.md). A Tek 4100
// stream has ESC and letters too, so the 4125's recogniser asks this first.
inline bool hasSixelIntroducer(std::span<const std::uint8_t> bytes) {
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::size_t at;
    if (bytes[i] == 0x90) {
      at = i + 1;
    } else if (bytes[i] == 0x1B && i + 1 < bytes.size() && bytes[i + 1] == 'P') {
      at = i + 2;
    } else {
      continue;
    }
    while (at < bytes.size() && ((bytes[at] >= '0' && bytes[at] <= '9') || bytes[at] == ';')) ++at;
    if (at < bytes.size() && bytes[at] == 'q') return true;
  }
  return false;
}

}  // namespace lattice::devices
