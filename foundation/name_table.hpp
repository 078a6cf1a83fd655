#pragma once
// Tables of named things: an enum's values and their spellings on the command
// line and in files, a device's named presets. One way to list the names
// ("a, b, c", as every "use one of ..." message gives them), to find an entry
// by name, and to go between an enum value and its name.
//
// Method: a table is a small array or vector read front to back (a handful
// of entries; a map would cost more than it saves). An entry is either a
// {value, name} pair (EnumName), a struct with a `name` member (what the
// table describes besides) or just a name; names may be std::string or
// std::string_view.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace lattice {

// One spelling of an enum value.
template <class Enum>
using EnumName = std::pair<Enum, std::string_view>;

// The entry's name: a pair's second, a `name` member, or the entry itself
// when it is a name (a plain list of names).
template <class Entry>
std::string_view entryName(const Entry& entry) {
  if constexpr (std::is_convertible_v<const Entry&, std::string_view>)
    return entry;
  else if constexpr (requires { entry.name; })
    return entry.name;
  else
    return entry.second;
}

// "a, b, c": every entry's name, in table order.
template <class Table>
std::string namesOf(const Table& table) {
  std::string names;
  for (const auto& entry : table) {
    if (!names.empty()) names += ", ";
    names += entryName(entry);
  }
  return names;
}

// Every entry's name, in table order (for CLI11's IsMember check).
template <class Table>
std::vector<std::string> nameList(const Table& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entryName(entry));
  return names;
}

// "a, b or c": the same names as a sentence, for "must be ..." messages.
template <class Table>
std::string choicesOf(const Table& table) {
  std::string names;
  std::size_t left = std::size(table);
  for (const auto& entry : table) {
    if (!names.empty()) names += left == 1 ? " or " : ", ";
    names += entryName(entry);
    --left;
  }
  return names;
}

// The entry called `name`, or null.
template <class Table>
auto findNamed(const Table& table, std::string_view name) -> decltype(&*std::begin(table)) {
  for (const auto& entry : table)
    if (entryName(entry) == name) return &entry;
  return nullptr;
}

// The value an EnumName table spells `name`, or none.
template <class Table>
auto valueNamed(const Table& table, std::string_view name) -> std::optional<decltype(std::begin(table)->first)> {
  if (const auto* entry = findNamed(table, name)) return entry->first;
  return std::nullopt;
}

// The name an EnumName table gives `value`, or `otherwise`.
template <class Table, class Enum>
std::string_view nameOfValue(const Table& table, Enum value, std::string_view otherwise = "unknown") {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return otherwise;
}

// The value of an EnumName table whose underlying integer is `code` (a file's
// field), or none.
template <class Table>
auto valueWithCode(const Table& table, std::uint64_t code) -> std::optional<decltype(std::begin(table)->first)> {
  for (const auto& [v, name] : table)
    if (static_cast<std::uint64_t>(v) == code) return v;
  return std::nullopt;
}

}  // namespace lattice
