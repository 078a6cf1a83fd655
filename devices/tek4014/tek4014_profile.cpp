#include "devices/tek4014/tek4014_profile.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"

namespace lattice::tek4014 {
namespace {
constexpr std::string_view kContext = "tek4014 profile";
constexpr std::string_view kKeys = "bits, dither, baud";
}  // namespace

const char* ditherName(Tek4014Dither dither) {
  switch (dither) {
    case Tek4014Dither::FloydSteinberg: return "floyd-steinberg";
    case Tek4014Dither::Ordered: return "ordered";
    case Tek4014Dither::Threshold: return "threshold";
  }
  return "?";
}

void applyOverride(Tek4014Profile& profile, std::string_view keyValue) {
  Tek4014Profile p = profile;  // a rejected override leaves the profile as it was
  const KeyValue kv = splitKeyValue(kContext, keyValue, kKeys);
  if (kv.key == "bits") {
    p.addressBits = parseIntSetting(kContext, kv);
    if (p.addressBits != 10 && p.addressBits != 12)
      throw Error(ErrorKind::Usage, fmt::format("{}: bits={} must be 10 (1024x780) or 12 (4096x3120)", kContext,
                                                kv.value));
  } else if (kv.key == "dither") {
    if (kv.value == "floyd-steinberg") p.dither = Tek4014Dither::FloydSteinberg;
    else if (kv.value == "ordered") p.dither = Tek4014Dither::Ordered;
    else if (kv.value == "threshold") p.dither = Tek4014Dither::Threshold;
    else
      throw Error(ErrorKind::Usage, fmt::format("{}: dither={} must be floyd-steinberg, ordered or threshold",
                                                kContext, kv.value));
  } else if (kv.key == "baud") {
    p.line.baud = parseIntSetting(kContext, kv);
    if (p.line.baud <= 0)
      throw Error(ErrorKind::Usage, fmt::format("{}: baud={} must be positive", kContext, kv.value));
  } else {
    unknownSetting(kContext, kv, kKeys);
  }
  profile = p;
}

void applyOverrides(Tek4014Profile& profile, const std::vector<std::string>& keyValues) {
  for (const auto& kv : keyValues) applyOverride(profile, kv);
}

std::string describe(const Tek4014Profile& p) {
  return fmt::format("bits={}\nwidth={}\nheight={}\ndither={}\nbaud={}\n", p.addressBits, p.width(), p.height(),
                     ditherName(p.dither), p.line.baud);
}

}  // namespace lattice::tek4014
