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

}  // namespace lattice::devices
