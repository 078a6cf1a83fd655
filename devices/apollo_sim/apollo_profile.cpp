#include "devices/apollo_sim/apollo_profile.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <iterator>

#include "foundation/error.hpp"

namespace lattice::apollo {

ApolloProfile dn660Profile(int planes) {
  if (planes != 4 && planes != 8)
    throw Error(ErrorKind::Usage, fmt::format("a DN660 has 4 or 8 bit planes, not {}: use dn660-4 or dn660", planes));
  ApolloProfile p;
  p.name = planes == 8 ? "dn660" : "dn660-4";
  p.model = fmt::format("Apollo DN660, 1024x1024, {} planes", planes);
  p.width = 1024;
  p.height = 1024;
  p.planes = planes;
  return p;
}

ApolloProfile dn580Profile() {
  ApolloProfile p;
  p.name = "dn580";
  p.model = "Apollo DN580, 1280x1024, 8 planes";
  p.width = 1280;
  p.height = 1024;
  p.planes = 8;
  return p;
}

namespace {

using P = ApolloProfile;

constexpr std::string_view kModelNames[] = {"dn660", "dn660-8", "dn660-4", "dn580"};
constexpr P (*kModels[])() = {[] { return dn660Profile(8); }, [] { return dn660Profile(8); },
                              [] { return dn660Profile(4); }, dn580Profile};  // kModelNames' order
static_assert(std::size(kModels) == std::size(kModelNames));

double modelIndex(const P& p) {
  const auto* at = std::find(std::begin(kModelNames), std::end(kModelNames), p.name);
  return static_cast<double>(at - std::begin(kModelNames));
}

std::string number(int n) { return fmt::format("{}", n); }

// The one key picks a model; the rest follows from it.
constexpr Setting<P> kSettings[] = {
    {"profile", SettingKind::Choice, {}, &choicesIn<kModelNames>,
     "the display: a DN660 colour node with 8 or 4 bit planes (dn660-8 is dn660), or a DN580 at 1280x1024",
     modelIndex, [](P& p, double i) { p = kModels[static_cast<std::size_t>(i)](); }, nullptr, true},
    reported<P>("model", [](const P& p) { return p.model; }),
    reported<P>("width", [](const P& p) { return number(p.width); }),
    reported<P>("height", [](const P& p) { return number(p.height); }),
    reported<P>("planes", [](const P& p) { return number(p.planes); }),
};

constexpr SettingsSchema<P> kSchema{"apollo profile", kSettings, kModels[0]};

}  // namespace

const SettingsSchema<ApolloProfile>& apolloSettings() { return kSchema; }

std::vector<std::string> apolloProfileNames() { return {std::begin(kModelNames), std::end(kModelNames)}; }

ApolloProfile apolloProfileByName(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kModelNames); ++i)
    if (kModelNames[i] == name) return kModels[i]();
  throw Error(ErrorKind::Usage,
              fmt::format("unknown Apollo model '{}': use one of {}", name, fmt::join(apolloProfileNames(), ", ")));
}

void applyOverrides(ApolloProfile& profile, const std::vector<std::string>& keyValues) {
  applySettings(kSchema, profile, keyValues);
}

std::string describe(const ApolloProfile& profile) { return describeSettings(kSchema, profile); }

}  // namespace lattice::apollo
