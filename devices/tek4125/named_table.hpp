#pragma once
// Lookup by name in a small table of named things (form sets, strategies):
// the 4125's spelling of the "unknown name, use one of ..." error over
// foundation/name_table.hpp. A --set value is checked against the names
// before it gets here (the profile's settings table); this catches a
// profile built in code.
#include <fmt/format.h>

#include <string_view>
#include <vector>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice::tek4125 {

using lattice::namesOf;

// The entry called `name`, or lattice::Error(Usage) naming what it is and the choices.
template <class T>
const T& findNamed(const std::vector<T>& table, std::string_view name, std::string_view what) {
  if (const T* entry = lattice::findNamed(table, name)) return *entry;
  throw Error(ErrorKind::Usage,
              fmt::format("tek4125 profile: no {} is called '{}'; use one of {} (docs/tek4125.md)", what, name,
                          namesOf(table)));
}

}  // namespace lattice::tek4125
