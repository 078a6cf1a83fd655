#pragma once
// A device profile's `--set key=value` settings, each declared once.
//
// Method: a profile lists its settings in one table, an array of Setting
// rows: the key, what it takes (a whole number, a number, on/off, or one of
// some names), the range or the names, a help line saying why a user would
// set it, and how the row reads and writes the profile. Applying a setting,
// the key list of an error, describe() and the Markdown table of docs/cli.md
// are all read from that table, so a key is spelled in one place and the
// docs cannot drift from the code (tests/devices/shared regenerates them).
// Every number goes through foundation/number_text.hpp and every size through
// foundation/byte_count.hpp, so NaN, infinities and values out of range are
// refused there, once. A default is the value
// the profile starts with, read through its row, never written twice.
//
// A value travels between the table and the profile as a double: the number
// itself, 0 or 1 for a switch, or the index of a name among the choices (a
// bool is choice 0 or not; an enum's values are its names in order). A
// setting that may be left unset (a std::optional field: "each lattice's own",
// "no budget") names that state with a word of its own (`unset`), which it
// takes and shows, and travels as NaN, which no typed number can be. Plain
// fields are read and written through member pointers (whole<&P::width>);
// a setting that is not one field (a preset, a character spelled as a name)
// gives its own pair of captureless functions. Rows are constant data with
// plain function pointers, so a table sits in flash on the firmware.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "foundation/key_value.hpp"
#include "foundation/name_table.hpp"
#include "foundation/number_text.hpp"

namespace lattice {

enum class SettingKind {
  Whole,     // a whole number in `range`
  Number,    // a finite number in `range`
  Switch,    // on or off (yes/no, true/false, 1/0 are read too)
  Bytes,     // a size in bytes: 57600, 56K, 8MiB (foundation/byte_count.hpp)
  Choice,    // one of `choices()`
  Reported,  // shown by describe() (`report`), not taken by --set: it follows from other settings
};

using SettingChoices = std::span<const std::string_view>;

template <class Profile>
struct Setting {
  std::string_view key;
  SettingKind kind = SettingKind::Whole;
  NumberRange range{};
  SettingChoices (*choices)() = nullptr;  // Choice: the names, in the order of their index
  std::string_view help;                  // one line: why a user would set it
  double (*read)(const Profile&) = nullptr;
  void (*write)(Profile&, double) = nullptr;
  std::string (*report)(const Profile&) = nullptr;  // Reported: the text describe() shows
  // A preset: applySettings applies it before the other keys wherever it was
  // typed, so they refine it.
  bool preset = false;
  // Non-empty: the word for "not set" (the field is a std::optional), e.g.
  // "scene" for each lattice's own form, "none" for no budget.
  std::string_view unset{};
};

template <class Profile>
struct SettingsSchema {
  std::string_view context;  // how errors name the profile: "tek4125 profile"
  std::span<const Setting<Profile>> rows;
  Profile (*initial)();      // the profile before any --set: the defaults the docs give
  // Constraints a value's own range cannot say (ones over several keys, or
  // "4 or 8"), checked after every change; Error(Usage) when broken.
  void (*validate)(const Profile&) = nullptr;
};

// What docs/cli.md and the tests know of a row, without its profile type.
struct SettingInfo {
  std::string_view key;
  SettingKind kind = SettingKind::Whole;
  NumberRange range{};
  std::vector<std::string_view> choices;
  std::string initial;  // the value the profile starts with, as describe() shows it
  std::string_view help;
  std::string_view unset;  // the word for "not set", or empty
};

// The parts that do not depend on the profile (settings_schema.cpp).
namespace settings_detail {
// A row as the parts below see it.
struct RowType {
  SettingKind kind = SettingKind::Whole;
  NumberRange range{};
  SettingChoices choices;
  std::string_view unset;
};
// The key=value's value as the row's double (NaN: the unset word), or
// Error(Usage) naming the key and what it takes.
double parseValue(std::string_view context, const RowType& type, const KeyValue& kv);
std::string formatValue(const RowType& type, double value);
// Error(Usage) when a stored value is outside its range (a profile built in
// code); an unset value passes where the row may be unset.
void checkRange(std::string_view context, std::string_view key, const RowType& type, double value);
void checkChoice(std::string_view context, std::string_view key, SettingChoices choices, double index);
}  // namespace settings_detail

// "a whole number from 1 to 4096", "`on` or `off`", "`strict` or `compact`".
std::string settingTakes(const SettingInfo& info);
// The rows as a Markdown table: key | takes | default | why set it.
std::string settingsMarkdown(std::span<const SettingInfo> infos);

// The names of a static array, for a Choice row: &choicesIn<kNames>.
template <const auto& Names>
SettingChoices choicesIn() {
  return Names;
}

namespace settings_detail {

template <class M>
struct MemberOf;
template <class C, class T>
struct MemberOf<T C::*> {
  using Class = C;
};

// The field a path of member pointers leads to: p.*a, or (p.*a).*b.
template <auto First, auto... Rest, class Object>
constexpr auto& field(Object& object) {
  if constexpr (sizeof...(Rest) == 0)
    return object.*First;
  else
    return field<Rest...>(object.*First);
}

// The profile a path of member pointers starts from.
template <auto First, auto...>
struct PathStart {
  using Profile = typename MemberOf<decltype(First)>::Class;
};
template <auto... Path>
using ProfileOf = typename PathStart<Path...>::Profile;

template <auto... Path>
using FieldOf = std::remove_cvref_t<decltype(field<Path...>(std::declval<ProfileOf<Path...>&>()))>;

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

template <class T>
constexpr double toValue(const T& v) {
  if constexpr (IsOptional<T>::value)
    return v ? toValue(*v) : std::numeric_limits<double>::quiet_NaN();
  else if constexpr (std::is_enum_v<T>)
    return static_cast<double>(static_cast<std::underlying_type_t<T>>(v));
  else if constexpr (std::is_same_v<T, bool>)
    return v ? 1.0 : 0.0;
  else
    return static_cast<double>(v);
}

template <class T>
constexpr T fromValue(double v) {
  if constexpr (IsOptional<T>::value)
    return std::isnan(v) ? T{} : T{fromValue<typename T::value_type>(v)};
  else if constexpr (std::is_enum_v<T>)
    return static_cast<T>(static_cast<std::underlying_type_t<T>>(v));
  else if constexpr (std::is_same_v<T, bool>)
    return v != 0;
  else
    return static_cast<T>(v);
}

template <auto... Path>
constexpr Setting<ProfileOf<Path...>> fieldRow(std::string_view key, SettingKind kind, NumberRange range,
                                               SettingChoices (*choices)(), std::string_view help) {
  using P = ProfileOf<Path...>;
  return {key, kind, range, choices, help,
          [](const P& p) { return toValue(field<Path...>(p)); },
          [](P& p, double v) { field<Path...>(p) = fromValue<FieldOf<Path...>>(v); }};
}

}  // namespace settings_detail

// A whole-number field (p.width, or p.line.baud through two member pointers).
template <auto... Path>
constexpr auto whole(std::string_view key, NumberRange range, std::string_view help) {
  range.whole = true;
  return settings_detail::fieldRow<Path...>(key, SettingKind::Whole, range, nullptr, help);
}

template <auto... Path>
constexpr auto number(std::string_view key, NumberRange range, std::string_view help) {
  return settings_detail::fieldRow<Path...>(key, SettingKind::Number, range, nullptr, help);
}

// A size in bytes (an integer field, or an optional one).
template <auto... Path>
constexpr auto bytes(std::string_view key, std::string_view help) {
  return settings_detail::fieldRow<Path...>(key, SettingKind::Bytes, {1, 1e18, true}, nullptr, help);
}

// A bool field taking on or off.
template <auto... Path>
constexpr auto onOff(std::string_view key, std::string_view help) {
  return settings_detail::fieldRow<Path...>(key, SettingKind::Switch, {}, nullptr, help);
}

// A bool field (the first name false, any other true) or an enum field (its
// values in the order of the names) taking one of `Names`.
template <const auto& Names, auto... Path>
constexpr auto choice(std::string_view key, std::string_view help) {
  return settings_detail::fieldRow<Path...>(key, SettingKind::Choice, {}, &choicesIn<Names>, help);
}

// A field taking one of `Names`, stored as the entry of `Values` at the same
// index (a character spelled as a word: separator=space for ' ').
template <const auto& Names, const auto& Values, auto... Path>
constexpr auto choiceAs(std::string_view key, std::string_view help) {
  static_assert(std::size(Names) == std::size(Values), "a name for every value");
  using P = settings_detail::ProfileOf<Path...>;
  return Setting<P>{key, SettingKind::Choice, {}, &choicesIn<Names>, help,
                    [](const P& p) {
                      std::size_t i = 0;
                      while (i < std::size(Values) && !(Values[i] == settings_detail::field<Path...>(p))) ++i;
                      return static_cast<double>(i);  // past the names: a value none names
                    },
                    [](P& p, double v) { settings_detail::field<Path...>(p) = Values[static_cast<std::size_t>(v)]; }};
}

// The names of a table (foundation/name_table.hpp: EnumName pairs, or
// entries with a `name`), for a Choice row over an enum field: the table is
// the one spelling.
template <const auto& Table>
SettingChoices namesOfTable() {
  static const auto names = [] {
    std::array<std::string_view, std::size(Table)> n{};
    for (std::size_t i = 0; i < n.size(); ++i) n[i] = entryName(Table[i]);
    return n;
  }();
  return names;
}

// An enum field (or an optional one) whose values are 0, 1, 2... in the order
// of the entries of `Table`, which name them.
template <const auto& Table, auto... Path>
constexpr auto choiceInOrder(std::string_view key, std::string_view help) {
  return settings_detail::fieldRow<Path...>(key, SettingKind::Choice, {}, &namesOfTable<Table>, help);
}

// The row, which may be left unset, `word` naming that state ("scene", "none").
template <class Profile>
constexpr Setting<Profile> orUnset(Setting<Profile> row, std::string_view word) {
  row.unset = word;
  return row;
}

// An enum field taking one of the names of `Table`, stored as that entry's value.
template <const auto& Table, auto... Path>
constexpr auto choiceOf(std::string_view key, std::string_view help) {
  using P = settings_detail::ProfileOf<Path...>;
  constexpr bool optional = settings_detail::IsOptional<settings_detail::FieldOf<Path...>>::value;
  return Setting<P>{key, SettingKind::Choice, {}, &namesOfTable<Table>, help,
                    [](const P& p) {
                      const auto& value = settings_detail::field<Path...>(p);
                      if constexpr (optional)
                        if (!value) return std::numeric_limits<double>::quiet_NaN();
                      std::size_t i = 0;
                      while (i < std::size(Table) && Table[i].first != value) ++i;
                      return static_cast<double>(i);
                    },
                    [](P& p, double v) {
                      auto& value = settings_detail::field<Path...>(p);
                      if constexpr (optional)
                        if (std::isnan(v)) return void(value.reset());
                      value = Table[static_cast<std::size_t>(v)].first;
                    }};
}

template <class Profile>
constexpr Setting<Profile> reported(std::string_view key, std::string (*report)(const Profile&)) {
  return {key, SettingKind::Reported, {}, nullptr, {}, nullptr, nullptr, report};
}

// The rows --set takes (every row but the Reported ones).
template <class Profile>
bool settable(const Setting<Profile>& row) {
  return row.kind != SettingKind::Reported;
}

template <class Profile>
SettingChoices rowChoices(const Setting<Profile>& row) {
  return row.choices ? row.choices() : SettingChoices{};
}

template <class Profile>
settings_detail::RowType rowType(const Setting<Profile>& row) {
  return {row.kind, row.range, rowChoices(row), row.unset};
}

// "a, b, c": the keys --set takes, in table order.
template <class Profile>
std::string settingKeys(const SettingsSchema<Profile>& schema) {
  std::string keys;
  for (const Setting<Profile>& row : schema.rows) {
    if (!settable(row)) continue;
    if (!keys.empty()) keys += ", ";
    keys += row.key;
  }
  return keys;
}

template <class Profile>
const Setting<Profile>* findSetting(const SettingsSchema<Profile>& schema, std::string_view key) {
  for (const Setting<Profile>& row : schema.rows)
    if (settable(row) && row.key == key) return &row;
  return nullptr;
}

// The row's value in `profile`, as describe() shows it and --set takes it back.
template <class Profile>
std::string settingText(const Setting<Profile>& row, const Profile& profile) {
  if (row.kind == SettingKind::Reported) return row.report(profile);
  return settings_detail::formatValue(rowType(row), row.read(profile));
}

// One "key=value": unknown keys, values that are not the row's kind or are
// outside its range, and profiles the schema's validate refuses throw
// Error(Usage) naming the key and what it takes; the profile is then left as
// it was.
template <class Profile>
void applySetting(const SettingsSchema<Profile>& schema, Profile& profile, std::string_view keyValue) {
  const std::string keys = settingKeys(schema);
  const KeyValue kv = splitKeyValue(schema.context, keyValue, keys);
  const Setting<Profile>* row = findSetting(schema, kv.key);
  if (!row) unknownSetting(schema.context, kv, keys);
  Profile changed = profile;
  row->write(changed, settings_detail::parseValue(schema.context, rowType(*row), kv));
  if (schema.validate) schema.validate(changed);
  profile = changed;
}

// Presets first, wherever they were typed, then the rest in order.
template <class Profile>
void applySettings(const SettingsSchema<Profile>& schema, Profile& profile, const std::vector<std::string>& keyValues) {
  const auto isPreset = [&](std::string_view keyValue) {
    const std::string_view key = keyValue.substr(0, keyValue.find('='));
    const Setting<Profile>* row = findSetting(schema, key);
    return row && row->preset;
  };
  for (const std::string& kv : keyValues)
    if (isPreset(kv)) applySetting(schema, profile, kv);
  for (const std::string& kv : keyValues)
    if (!isPreset(kv)) applySetting(schema, profile, kv);
}

// "key=value\n" for every row, in table order.
template <class Profile>
std::string describeSettings(const SettingsSchema<Profile>& schema, const Profile& profile) {
  std::string text;
  for (const Setting<Profile>& row : schema.rows) {
    text += row.key;
    text += '=';
    text += settingText(row, profile);
    text += '\n';
  }
  return text;
}

// The "key=value" settings that take `from` to `to` (what --set would have to say).
template <class Profile>
std::vector<std::string> settingsChanged(const SettingsSchema<Profile>& schema, const Profile& from,
                                         const Profile& to) {
  std::vector<std::string> changed;
  for (const Setting<Profile>& row : schema.rows) {
    if (!settable(row)) continue;
    const std::string value = settingText(row, to);
    if (value != settingText(row, from)) changed.push_back(std::string(row.key) + "=" + value);
  }
  return changed;
}

// Error(Usage) for a numeric field outside its row's range, or a field no
// name of its row's choices stands for: for a profile built in code rather
// than through --set (a driver checks what it is given).
template <class Profile>
void checkSettings(const SettingsSchema<Profile>& schema, const Profile& profile) {
  for (const Setting<Profile>& row : schema.rows) {
    const double value = row.kind == SettingKind::Reported ? 0.0 : row.read(profile);
    if (!row.unset.empty() && std::isnan(value)) continue;
    if (row.kind == SettingKind::Whole || row.kind == SettingKind::Number || row.kind == SettingKind::Bytes)
      settings_detail::checkRange(schema.context, row.key, rowType(row), value);
    else if (row.kind == SettingKind::Choice)
      settings_detail::checkChoice(schema.context, row.key, rowChoices(row), value);
  }
}

// The settable rows, with the values the schema's initial profile has.
template <class Profile>
std::vector<SettingInfo> settingInfos(const SettingsSchema<Profile>& schema) {
  const Profile initial = schema.initial();
  std::vector<SettingInfo> infos;
  for (const Setting<Profile>& row : schema.rows) {
    if (!settable(row)) continue;
    const SettingChoices names = rowChoices(row);
    infos.push_back(
        {row.key, row.kind, row.range, {names.begin(), names.end()}, settingText(row, initial), row.help, row.unset});
  }
  return infos;
}

}  // namespace lattice
