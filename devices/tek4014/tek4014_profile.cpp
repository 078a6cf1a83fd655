#include "devices/tek4014/tek4014_profile.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice::tek4014 {
namespace {

using P = Tek4014Profile;

constexpr std::string_view kContext = "tek4014 profile";

constexpr std::string_view kDitherNames[] = {"floyd-steinberg", "ordered", "threshold"};  // Tek4014Dither's order

// Every key of the profile, in describe()'s order (docs/cli.md shows this
// table); the screen follows from the address bits.
constexpr Setting<P> kSettings[] = {
    whole<&P::addressBits>("bits", {10, 12},
                           "address bits, 10 or 12: 12 for the 4014's enhanced graphics module (a 4096x3120 screen)"),
    reported<P>("width", [](const P& p) { return fmt::format("{}", p.width()); }),
    reported<P>("height", [](const P& p) { return fmt::format("{}", p.height()); }),
    choice<kDitherNames, &P::dither>("dither",
        "how grey becomes lit and dark dots: error diffusion, a Bayer matrix or a plain threshold"),
    whole<&P::line, &LineFormat::baud>("baud", {1}, "the line's rate: only the reported transmit time follows it"),
};

void validate(const P& p) {
  if (p.addressBits != 10 && p.addressBits != 12)
    throw Error(ErrorKind::Usage,
                fmt::format("{}: {} address bits are not supported; use 10 (1024x780) or 12 (4096x3120)",
                            kContext, p.addressBits));
}

constexpr SettingsSchema<P> kSchema{kContext, kSettings, [] { return P{}; }, validate};

}  // namespace

const SettingsSchema<Tek4014Profile>& tek4014Settings() { return kSchema; }

std::string_view ditherName(Tek4014Dither dither) {
  const auto i = static_cast<std::size_t>(dither);
  return i < std::size(kDitherNames) ? kDitherNames[i] : "?";
}

void applyOverride(Tek4014Profile& profile, std::string_view keyValue) { applySetting(kSchema, profile, keyValue); }

void applyOverrides(Tek4014Profile& profile, const std::vector<std::string>& keyValues) {
  applySettings(kSchema, profile, keyValues);
}

std::string describe(const Tek4014Profile& profile) { return describeSettings(kSchema, profile); }

}  // namespace lattice::tek4014
