#pragma once
// The emulator's readings (devices/tek4125/tek4125_readings.hpp) spelled as
// key=value, so a test can list the combinations it decodes a stream under.
// Test support only: the readings are no user setting.
#include <string>
#include <string_view>
#include <vector>

#include "devices/tek4125/tek4125_readings.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::tek4125::test {

namespace readings_detail {
using R = Tek4125Readings;
inline constexpr std::string_view kPowerUpMaps[] = {"pgplot", "ral-cgm"};  // Tek4125PowerUpMap's order
inline constexpr std::string_view kRrOrigins[] = {"screen", "viewport"};
inline constexpr std::string_view kRhOrigins[] = {"viewport", "screen"};
inline constexpr std::string_view kPixelBits[] = {"ru", "surface"};
inline constexpr std::string_view kRasterRows[] = {"up", "down"};
inline constexpr Setting<R> kRows[] = {
    choice<kPowerUpMaps, &R::powerUpMap>("power-up-map", "the colour map before any TG"),
    choice<kRrOrigins, &R::rrFromViewport>("rr-origin", "RR corners relative to the screen or the viewport"),
    choice<kRhOrigins, &R::rhFromScreen>("rh-origin", "RH relative to the viewport or the screen"),
    whole<&R::surfacePlanes>("surface-planes", {0, 8}, "planes of surface 1 before any RD (0: all)"),
    choice<kPixelBits, &R::pixelBitsFromSurface>("pixel-bits", "RP and RL packed by RU's bits or the surface's planes"),
    choice<kRasterRows, &R::rasterRowsDown>("raster-rows", "the beam after RS: lower left up, or upper left down"),
};
inline constexpr SettingsSchema<R> kSchema{"tek4125 readings", kRows, [] { return R{}; }};
}  // namespace readings_detail

// The readings with each "key=value" applied to the defaults.
inline Tek4125Readings readingsOf(const std::vector<std::string>& keyValues) {
  Tek4125Readings readings;
  applySettings(readings_detail::kSchema, readings, keyValues);
  return readings;
}

}  // namespace lattice::tek4125::test
