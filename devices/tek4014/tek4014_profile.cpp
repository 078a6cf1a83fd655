#include "devices/tek4014/tek4014_profile.hpp"

#include <fmt/format.h>

#include <array>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"
#include "foundation/name_table.hpp"

namespace lattice::tek4014 {
namespace {
constexpr std::string_view kContext = "tek4014 profile";
constexpr std::string_view kKeys = "bits, dither, baud";
}  // namespace

namespace {
constexpr std::array<EnumName<Tek4014Dither>, 3> kDitherNames = {{
    {Tek4014Dither::FloydSteinberg, "floyd-steinberg"},
    {Tek4014Dither::Ordered, "ordered"},
    {Tek4014Dither::Threshold, "threshold"},
}};
}  // namespace

std::string_view ditherName(Tek4014Dither dither) { return nameOfValue(kDitherNames, dither, "?"); }

void applyOverride(Tek4014Profile& profile, std::string_view keyValue) {
  Tek4014Profile p = profile;  // a rejected override leaves the profile as it was
  const KeyValue kv = splitKeyValue(kContext, keyValue, kKeys);
  if (kv.key == "bits") {
    p.addressBits = parseIntSetting(kContext, kv);
    if (p.addressBits != 10 && p.addressBits != 12)
      throw Error(ErrorKind::Usage, fmt::format("{}: bits={} must be 10 (1024x780) or 12 (4096x3120)", kContext,
                                                kv.value));
  } else if (kv.key == "dither") {
    const auto dither = valueNamed(kDitherNames, kv.value);
    if (!dither)
      throw Error(ErrorKind::Usage,
                  fmt::format("{}: dither={} must be {}", kContext, kv.value, choicesOf(kDitherNames)));
    p.dither = *dither;
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
