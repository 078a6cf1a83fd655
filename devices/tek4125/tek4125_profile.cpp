#include "devices/tek4125/tek4125_profile.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"

namespace lattice {

namespace {

constexpr const char* kKeys =
    "width, height, planes, palette-bits, reserved, baud, data-bits, parity, stop-bits, xon-xoff";

void requireRange(const char* key, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125 profile: {}={} is out of range; use a value in {}..{}", key, value, lo, hi));
}

}  // namespace

void Tek4125Profile::validate() const {
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
}

void applyOverride(Tek4125Profile& profile, std::string_view keyValue) {
  constexpr std::string_view kContext = "tek4125 profile";
  Tek4125Profile p = profile;  // a rejected override leaves the profile as it was
  const KeyValue kv = splitKeyValue(kContext, keyValue, kKeys);
  const std::string_view key = kv.key;
  if (key == "width") p.width = parseIntSetting(kContext, kv);
  else if (key == "height") p.height = parseIntSetting(kContext, kv);
  else if (key == "planes") p.planes = parseIntSetting(kContext, kv);
  else if (key == "palette-bits") p.paletteBits = parseIntSetting(kContext, kv);
  else if (key == "reserved") p.reserved = parseIntSetting(kContext, kv);
  else if (key == "baud") p.baud = parseIntSetting(kContext, kv);
  else if (key == "data-bits") p.dataBits = parseIntSetting(kContext, kv);
  else if (key == "stop-bits") p.stopBits = parseIntSetting(kContext, kv);
  else if (key == "xon-xoff") p.xonXoff = parseSwitchSetting(kContext, kv);
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
      "width={}\nheight={}\nplanes={}\npalette-bits={}\nreserved={}\nbaud={}\ndata-bits={}\nparity={}\n"
      "stop-bits={}\nxon-xoff={}\n",
      p.width, p.height, p.planes, p.paletteBits, p.reserved, p.baud, p.dataBits, p.parity ? "even" : "none",
      p.stopBits, p.xonXoff ? "on" : "off");
}

}  // namespace lattice
