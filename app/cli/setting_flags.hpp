#pragma once
// Command-line flags read from a settings schema (foundation/settings_schema.hpp):
// one `--key` a row, its help the row's help line, its check the row's
// range (numberIn) or names (CLI::IsMember), its default the schema's
// initial value. The flags only collect text; applySettingFlags then writes
// each given value through the schema's own parser (applySetting), so a
// flag and `--set key=value` are read by the same code and a key is spelled
// once, in the schema.
#include <CLI/CLI.hpp>

#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/number_flags.hpp"
#include "foundation/settings_schema.hpp"

namespace lattice::app {

// The text of each flag given, by key.
using SettingFlagValues = std::map<std::string, std::string, std::less<>>;

// Adds `--key` for each of `keys` (each a row of `schema`), listed under
// `group`; `shortNames` gives a row a short form too ("colors" -> "-k").
template <class Profile>
void addSettingFlags(CLI::App* cmd, const SettingsSchema<Profile>& schema, const Profile& initial,
                     SettingFlagValues& values, std::span<const std::string_view> keys, const std::string& group,
                     const std::map<std::string_view, std::string_view>& shortNames = {}) {
  for (std::string_view key : keys) {
    const Setting<Profile>* row = findSetting(schema, key);
    if (!row) throw std::logic_error("no setting " + std::string(key) + " in " + std::string(schema.context));
    std::string name = "--" + std::string(key);
    if (const auto s = shortNames.find(key); s != shortNames.end()) name = "-" + std::string(s->second) + "," + name;
    CLI::Option* option =
        cmd->add_option_function<std::string>(
               name, [&values, key = std::string(key)](const std::string& text) { values[key] = text; },
               std::string(row->help))
            ->default_str(settingText(*row, initial))
            ->group(group);
    if (row->kind == SettingKind::Choice) {
      option->type_name("TEXT");
      const SettingChoices choices = rowChoices(*row);
      option->check(CLI::IsMember(std::vector<std::string>(choices.begin(), choices.end())));
    } else if (row->kind == SettingKind::Whole || row->kind == SettingKind::Number) {
      option->type_name(row->kind == SettingKind::Whole ? "INT" : "FLOAT");
      option->check(numberIn(row->range));
    }
  }
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
