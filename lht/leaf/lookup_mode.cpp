#include "lht/leaf/lookup_mode.hpp"

#include <fmt/format.h>

#include <array>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice::lht {

namespace {

constexpr std::array<EnumName<LatticeLookup>, 2> kLookups = {{
    {LatticeLookup::Thesis, "thesis"},
    {LatticeLookup::Blend, "blend"},
}};

}  // namespace

std::string_view latticeLookupName(LatticeLookup lookup) { return nameOfValue(kLookups, lookup); }

std::string latticeLookupChoices() { return namesOf(kLookups); }

std::optional<LatticeLookup> latticeLookupFromName(std::string_view name) { return valueNamed(kLookups, name); }

LatticeLookup parseLatticeLookup(std::string_view name, std::string_view what) {
  if (const auto lookup = latticeLookupFromName(name)) return *lookup;
  throw Error(ErrorKind::Usage,
              fmt::format("{}: unknown lattice look-up '{}'; use one of {}", what, name, latticeLookupChoices()));
}

}  // namespace lattice::lht
