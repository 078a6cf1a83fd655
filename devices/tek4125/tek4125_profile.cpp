#include "devices/tek4125/tek4125_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"

namespace lattice::tek4125 {

namespace {

constexpr const char* kKeys =
    "profile, width, height, planes, palette-bits, reserved, baud, data-bits, parity, stop-bits, xon-xoff, "
    "power-up-map, strategy, rr-origin, rh-origin, surface-planes, pixel-bits, raster-rows, progressive, xy-short, ru-bits";

void requireRange(const char* key, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125 profile: {}={} is out of range; use a value in {}..{}", key, value, lo, hi));
}

// false for `usual`, true for `other`.
bool originSetting(const KeyValue& kv, std::string_view usual, std::string_view other) {
  if (kv.value == usual) return false;
  if (kv.value == other) return true;
  throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: {}={} must be {} or {}", kv.key, kv.value, usual, other));
}

}  // namespace

void Tek4125Profile::validate() const {
  (void)formSet();  // throws for an unknown form set
  (void)tek4125Strategy(strategy);
  // 4095 is the largest 12-bit pixel coordinate the raster commands can address.
  requireRange("width", width, 1, 4096);
  requireRange("height", height, 1, 4096);
  if (planes != 4 && planes != 8)
    throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: planes={} is not supported; use planes=4 or planes=8", planes));
  requireRange("palette-bits", paletteBits, 3, 24);
  requireRange("reserved", reserved, 0, colorMapSize() - 2);
  requireRange("baud", baud, 50, 1000000);
  requireRange("data-bits", dataBits, 7, 8);
  requireRange("stop-bits", stopBits, 1, 2);
  requireRange("surface-planes", surfacePlanes, 0, planes);
}

int Tek4125Profile::pixelBitsFor(int colours) const {
  const int needed = colours + reserved;
  if (needed <= 16) return 4;
  if (ruBitsFit && formSet().fittedDepth) return std::min(planes, int(std::bit_width(unsigned(needed - 1))));
  return planes;
}

void applyOverride(Tek4125Profile& profile, std::string_view keyValue) {
  constexpr std::string_view kContext = "tek4125 profile";
  Tek4125Profile p = profile;  // a rejected override leaves the profile as it was
  const KeyValue kv = splitKeyValue(kContext, keyValue, kKeys);
  const std::string_view key = kv.key;
  if (key == "profile") p.forms = tek4125Forms(kv.value).name;
  else if (key == "strategy") p.strategy = tek4125Strategy(kv.value).name;
  else if (key == "rr-origin") p.rrFromViewport = originSetting(kv, "screen", "viewport");
  else if (key == "rh-origin") p.rhFromScreen = originSetting(kv, "viewport", "screen");
  else if (key == "surface-planes") p.surfacePlanes = parseIntSetting(kContext, kv);
  else if (key == "pixel-bits") p.pixelBitsFromSurface = originSetting(kv, "ru", "surface");
  else if (key == "raster-rows") p.rasterRowsDown = originSetting(kv, "up", "down");
  else if (key == "power-up-map") {
    if (kv.value == "pgplot") p.powerUpMap = Tek4125PowerUpMap::Pgplot;
    else if (kv.value == "ral-cgm") p.powerUpMap = Tek4125PowerUpMap::RalCgm;
    else throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: power-up-map={} must be pgplot or ral-cgm", kv.value));
  } else if (key == "width") p.width = parseIntSetting(kContext, kv);
  else if (key == "height") p.height = parseIntSetting(kContext, kv);
  else if (key == "planes") p.planes = parseIntSetting(kContext, kv);
  else if (key == "palette-bits") p.paletteBits = parseIntSetting(kContext, kv);
  else if (key == "reserved") p.reserved = parseIntSetting(kContext, kv);
  else if (key == "baud") p.baud = parseIntSetting(kContext, kv);
  else if (key == "data-bits") p.dataBits = parseIntSetting(kContext, kv);
  else if (key == "stop-bits") p.stopBits = parseIntSetting(kContext, kv);
  else if (key == "xon-xoff") p.xonXoff = parseSwitchSetting(kContext, kv);
  else if (key == "progressive") p.progressive = parseSwitchSetting(kContext, kv);
  else if (key == "xy-short") p.xyShort = parseSwitchSetting(kContext, kv);
  else if (key == "ru-bits") p.ruBitsFit = originSetting(kv, "planes", "fit");
  else if (key == "parity") {
    if (kv.value == "none") p.parity = false;
    else if (kv.value == "even" || kv.value == "odd") p.parity = true;  // only its bit time matters here
    else throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: parity={} must be none, even or odd", kv.value));
  } else {
    unknownSetting(kContext, kv, kKeys);
  }
  p.validate();
  profile = p;
}

void applyOverrides(Tek4125Profile& profile, const std::vector<std::string>& keyValues) {
  for (const auto& kv : keyValues) applyOverride(profile, kv);
}

std::string describe(const Tek4125Profile& p) {
  return fmt::format(
      "profile={}\nwidth={}\nheight={}\nplanes={}\npalette-bits={}\nreserved={}\nbaud={}\ndata-bits={}\n"
      "parity={}\nstop-bits={}\nxon-xoff={}\npower-up-map={}\nstrategy={}\nrr-origin={}\nrh-origin={}\n"
      "surface-planes={}\npixel-bits={}\nraster-rows={}\nprogressive={}\nxy-short={}\nru-bits={}\n",
      p.forms, p.width, p.height, p.planes, p.paletteBits, p.reserved, p.baud, p.dataBits, p.parity ? "even" : "none",
      p.stopBits, p.xonXoff ? "on" : "off", p.powerUpMap == Tek4125PowerUpMap::Pgplot ? "pgplot" : "ral-cgm",
      p.strategy, p.rrFromViewport ? "viewport" : "screen", p.rhFromScreen ? "screen" : "viewport", p.surfacePlanes,
      p.pixelBitsFromSurface ? "surface" : "ru", p.rasterRowsDown ? "down" : "up", p.progressive ? "on" : "off", p.xyShort ? "on" : "off",
      p.ruBitsFit ? "fit" : "planes");
}

}  // namespace lattice::tek4125
