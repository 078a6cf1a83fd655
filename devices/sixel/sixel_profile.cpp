#include "devices/sixel/sixel_profile.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "foundation/key_value.hpp"

namespace lattice::sixel {
namespace {

constexpr std::string_view kContext = "sixel profile";
constexpr std::string_view kKeys = "registers, width, height, p1, p2";

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(ErrorKind::Usage, fmt::format("{}: {}", kContext, what));
}

}  // namespace

void SixelProfile::validate() const {
  require(registers >= 2 && registers <= 256,
          fmt::format("registers={} is outside 2..256 (16 for a VT340, 256 for xterm with numColorRegisters)",
                      registers));
  require(width >= 1 && width <= 4096 && height >= 1 && height <= 4096,
          fmt::format("size {}x{} is outside 1..4096 in each direction", width, height));
  require(p1 >= 0 && p1 <= 9, fmt::format("p1={} is outside 0..9", p1));
  require(p2 >= 0 && p2 <= 2, fmt::format("p2={} is outside 0..2", p2));
}

void applyOverride(SixelProfile& profile, std::string_view keyValue) {
  SixelProfile p = profile;
  const KeyValue kv = splitKeyValue(kContext, keyValue, kKeys);
  if (kv.key == "registers") p.registers = parseIntSetting(kContext, kv);
  else if (kv.key == "width") p.width = parseIntSetting(kContext, kv);
  else if (kv.key == "height") p.height = parseIntSetting(kContext, kv);
  else if (kv.key == "p1") p.p1 = parseIntSetting(kContext, kv);
  else if (kv.key == "p2") p.p2 = parseIntSetting(kContext, kv);
  else unknownSetting(kContext, kv, kKeys);
  p.validate();
  profile = p;
}

void applyOverrides(SixelProfile& profile, const std::vector<std::string>& keyValues) {
  for (const auto& kv : keyValues) applyOverride(profile, kv);
}

std::string describe(const SixelProfile& p) {
  return fmt::format("registers={}\nwidth={}\nheight={}\np1={}\np2={}\n", p.registers, p.width, p.height, p.p1,
                     p.p2);
}

}  // namespace lattice::sixel
