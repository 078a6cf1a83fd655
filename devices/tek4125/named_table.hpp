#pragma once
// Lookup by name in a small table of named settings (form sets,
// strategies): one spelling of the "unknown name, use one of ..." error.
#include <fmt/format.h>

#include <string>
#include <string_view>
#include <vector>

#include "foundation/error.hpp"

namespace lattice::tek4125 {

// "a, b, c" from each entry's `name`.
template <class T>
std::string namesOf(const std::vector<T>& table) {
  std::string names;
  for (const T& entry : table) names += (names.empty() ? "" : ", ") + entry.name;
  return names;
}

// The entry called `name`, or lattice::Error(Usage) naming the key and the choices.
template <class T>
const T& findNamed(const std::vector<T>& table, std::string_view name, std::string_view key) {
  for (const T& entry : table)
    if (entry.name == name) return entry;
  throw Error(ErrorKind::Usage,
              fmt::format("tek4125 profile: {}={} is unknown; use one of {} (docs/tek4125.md)", key, name,
                          namesOf(table)));
}

}  // namespace lattice::tek4125
