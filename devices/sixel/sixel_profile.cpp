#include "devices/sixel/sixel_profile.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice::sixel {
namespace {

using P = SixelProfile;

// Every key of the profile, in describe()'s order (docs/cli.md shows this table).
constexpr Setting<P> kSettings[] = {
    whole<&P::registers>("registers", {2, 256},
                         "colour registers: 16 on a VT340; up to 256 for xterm with its numColorRegisters resource"),
    whole<&P::width>("width", {1, 4096},
                     "the widest raster the terminal takes (xterm's maxGraphicSize); a render fits within it"),
    whole<&P::height>("height", {1, 4096},
                      "the tallest raster the terminal takes (xterm's maxGraphicSize); a render fits within it"),
    whole<&P::p1>("p1", {0, 9},
                  "the DCS pixel aspect parameter, for a terminal that heeds it over the raster attributes' 1:1"),
    whole<&P::p2>("p2", {0, 2},
                  "the DCS background parameter (1: pixels no sixel sets stay as they were); Lattice sets every pixel"),
};

constexpr SettingsSchema<P> kSchema{"sixel profile", kSettings, [] { return P{}; },
                                    [](const P& p) { p.validate(); }};

}  // namespace

const SettingsSchema<SixelProfile>& sixelSettings() { return kSchema; }

// Every constraint is one key's range.
void SixelProfile::validate() const { checkSettings(kSchema, *this); }

void applyOverride(SixelProfile& profile, std::string_view keyValue) { applySetting(kSchema, profile, keyValue); }

void applyOverrides(SixelProfile& profile, const std::vector<std::string>& keyValues) {
  applySettings(kSchema, profile, keyValues);
}

std::string describe(const SixelProfile& profile) { return describeSettings(kSchema, profile); }

}  // namespace lattice::sixel
