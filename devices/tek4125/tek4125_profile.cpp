#include "devices/tek4125/tek4125_profile.hpp"

#include <fmt/format.h>

#include <charconv>

#include "util/error.hpp"

namespace lattice {

namespace {

constexpr const char* kKeys =
    "width, height, planes, palette-bits, reserved, baud, data-bits, parity, stop-bits, xon-xoff";

void requireRange(const char* key, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125 profile: {}={} is out of range; use a value in {}..{}", key, value, lo, hi));
}

int parseInt(std::string_view key, std::string_view text) {
  int v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125 profile: '{}={}' needs a whole number, e.g. {}=8", key, text, key));
  return v;
}

bool parseSwitch(std::string_view key, std::string_view text) {
  if (text == "on" || text == "yes" || text == "true" || text == "1") return true;
  if (text == "off" || text == "no" || text == "false" || text == "0") return false;
  throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: '{}={}' needs on or off", key, text));
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
  Tek4125Profile p = profile;  // a rejected override leaves the profile as it was
  const auto eq = keyValue.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125 profile: '{}' is not key=value (e.g. planes=4); keys: {}", keyValue, kKeys));
  const std::string_view key = keyValue.substr(0, eq);
  const std::string_view value = keyValue.substr(eq + 1);
  if (key == "width") p.width = parseInt(key, value);
  else if (key == "height") p.height = parseInt(key, value);
  else if (key == "planes") p.planes = parseInt(key, value);
  else if (key == "palette-bits") p.paletteBits = parseInt(key, value);
  else if (key == "reserved") p.reserved = parseInt(key, value);
  else if (key == "baud") p.baud = parseInt(key, value);
  else if (key == "data-bits") p.dataBits = parseInt(key, value);
  else if (key == "stop-bits") p.stopBits = parseInt(key, value);
  else if (key == "xon-xoff") p.xonXoff = parseSwitch(key, value);
  else if (key == "parity") {
    if (value == "none") p.parity = false;
    else if (value == "even" || value == "odd") p.parity = true;  // only its bit time matters here
    else throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: parity={} must be none, even or odd", value));
  } else {
    throw Error(ErrorKind::Usage, fmt::format("tek4125 profile: unknown key '{}'; keys: {}", key, kKeys));
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
