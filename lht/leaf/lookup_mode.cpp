#include "lht/leaf/lookup_mode.hpp"

#include <fmt/format.h>

#include <array>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice::lht {


std::string_view latticeLookupName(LatticeLookup lookup) { return nameOfValue(kLatticeLookupNames, lookup); }

std::string latticeLookupChoices() { return namesOf(kLatticeLookupNames); }

std::optional<LatticeLookup> latticeLookupFromName(std::string_view name) { return valueNamed(kLatticeLookupNames, name); }

LatticeLookup parseLatticeLookup(std::string_view name, std::string_view what) {
  if (const auto lookup = latticeLookupFromName(name)) return *lookup;
  throw Error(ErrorKind::Usage,
              fmt::format("{}: unknown lattice look-up '{}'; use one of {}", what, name, latticeLookupChoices()));
}

}  // namespace lattice::lht
