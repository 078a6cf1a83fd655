#pragma once
// A colour gun as a terminal takes it, 0..100 percent, and back: the Tek
// 4100 series' TG and the sixel colour register (DECGCI) both load RGB in
// percent. Both directions round to nearest, so 8 bits -> percent -> 8 bits
// moves a gun by at most kPercentRoundTripMaxDelta (checked over 0..255 in
// the tests). One definition for every driver and emulator that uses it.
#include <algorithm>
#include <cstdint>

namespace lattice::devices {

constexpr int percentOf8(std::uint8_t v8) { return (v8 * 100 + 127) / 255; }
// Out-of-range percents (a stream may send any) are clamped first.
constexpr std::uint8_t eightOfPercent(int percent) {
  return static_cast<std::uint8_t>((std::clamp(percent, 0, 100) * 255 + 50) / 100);
}
inline constexpr int kPercentRoundTripMaxDelta = 2;

}  // namespace lattice::devices
