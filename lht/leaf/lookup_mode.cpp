#include "lht/leaf/lookup_mode.hpp"

#include <fmt/format.h>

#include <array>
#include <utility>

#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

constexpr std::array<std::pair<LatticeLookup, std::string_view>, 2> kLookups = {{
    {LatticeLookup::Thesis, "thesis"},
    {LatticeLookup::Blend, "blend"},
}};

}  // namespace

std::string_view latticeLookupName(LatticeLookup lookup) {
  for (const auto& [l, name] : kLookups)
    if (l == lookup) return name;
  return "unknown";
}

std::string latticeLookupChoices() {
  std::string out;
  for (const auto& [l, name] : kLookups) out += fmt::format("{}{}", out.empty() ? "" : ", ", name);
  return out;
}

std::optional<LatticeLookup> latticeLookupFromName(std::string_view name) {
  for (const auto& [l, n] : kLookups)
    if (n == name) return l;
  return std::nullopt;
}

LatticeLookup parseLatticeLookup(std::string_view name, std::string_view what) {
  if (const auto lookup = latticeLookupFromName(name)) return *lookup;
  throw Error(ErrorKind::Usage,
              fmt::format("{}: unknown lattice look-up '{}'; use one of {}", what, name, latticeLookupChoices()));
}

}  // namespace lattice::lht
