#pragma once
// Command-line flags read from a settings schema (foundation/settings_schema.hpp):
// one `--key` a row, its help the row's help line, its check the row's
// range, names or sizes, its default the schema's initial value; a switch
// is a flag without a value. Each given value is written through the
// schema's own parser (applySetting): at once (addSettingFlagsInto), or
// collected and written once every flag is read (addSettingFlags, then
// applySettingFlags), where a row's value depends on another's. So a flag
// and `--set key=value` are read by the same code and a key is spelled once,
// in the schema.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "foundation/settings_schema.hpp"

namespace lattice::app {

// The text of each flag given, by key.
using SettingFlagValues = std::map<std::string, std::string, std::less<>>;

// The CLI11 check of a row's flag: the row's range, names or sizes, and its
// unset word (setting_flags.cpp); CLI11 names the flag in its message.
CLI::Validator settingFlagCheck(const settings_detail::RowType& type);

// What a flag does with its text once CLI11 has checked it.
using SettingFlagGiven = std::function<void(const std::string& key, const std::string& text)>;

// Adds `--key` for each of `keys` (each a row of `schema`), listed under
// `group`; `shortNames` gives a row a short form too ("colors" -> "-k").
template <class Profile>
void addSettingFlagsWith(CLI::App* cmd, const SettingsSchema<Profile>& schema, const Profile& initial,
                         const SettingFlagGiven& given, std::span<const std::string_view> keys,
                         const std::string& group, const std::map<std::string_view, std::string_view>& shortNames = {}) {
  for (std::string_view key : keys) {
    const Setting<Profile>* row = findSetting(schema, key);
    if (!row) throw std::logic_error("no setting " + std::string(key) + " in " + std::string(schema.context));
    std::string name = "--" + std::string(key);
    if (const auto s = shortNames.find(key); s != shortNames.end()) name = "-" + std::string(s->second) + "," + name;
    const std::string help(row->help);
    if (row->kind == SettingKind::Switch) {  // a switch is a flag: given is on
      cmd->add_flag_function(
             name, [given, key = std::string(key)](std::int64_t) { given(key, "on"); }, help)
          ->group(group);
      continue;
    }
    CLI::Option* option =
        cmd->add_option_function<std::string>(
               name, [given, key = std::string(key)](const std::string& text) { given(key, text); }, help)
            ->default_str(settingText(*row, initial))
            ->group(group);
    option->check(settingFlagCheck(rowType(*row)));
    option->type_name(row->kind == SettingKind::Whole    ? "INT"
                      : row->kind == SettingKind::Number ? "FLOAT"
                      : row->kind == SettingKind::Bytes  ? "SIZE"
                                                         : "TEXT");
  }
}

// The flags collect their text in `values`, to be written by applySettingFlags
// once every flag is read (where the order of the rows matters).
template <class Profile>
void addSettingFlags(CLI::App* cmd, const SettingsSchema<Profile>& schema, const Profile& initial,
                     SettingFlagValues& values, std::span<const std::string_view> keys, const std::string& group,
                     const std::map<std::string_view, std::string_view>& shortNames = {}) {
  addSettingFlagsWith(
      cmd, schema, initial, [&values](const std::string& key, const std::string& text) { values[key] = text; }, keys,
      group, shortNames);
}

// The flags write `profile` through the schema as CLI11 reads them.
template <class Profile>
void addSettingFlagsInto(CLI::App* cmd, const SettingsSchema<Profile>& schema, Profile& profile,
                         std::span<const std::string_view> keys, const std::string& group) {
  addSettingFlagsWith(
      cmd, schema, profile,
      [&schema, &profile](const std::string& key, const std::string& text) {
        applySetting(schema, profile, key + "=" + text);
      },
      keys, group);
}

// Every settable key of `schema`, in its order.
template <class Profile>
std::vector<std::string_view> settableKeys(const SettingsSchema<Profile>& schema) {
  std::vector<std::string_view> keys;
  for (const Setting<Profile>& row : schema.rows)
    if (settable(row)) keys.push_back(row.key);
  return keys;
}

// Writes each given flag's value into `profile` through the schema, in the
// schema's row order.
template <class Profile>
void applySettingFlags(const SettingsSchema<Profile>& schema, Profile& profile, const SettingFlagValues& values) {
  for (const Setting<Profile>& row : schema.rows)
    if (const auto v = values.find(row.key); v != values.end())
      applySetting(schema, profile, std::string(row.key) + "=" + v->second);
}

}  // namespace lattice::app
