#include "foundation/settings_schema.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice {
namespace settings_detail {

double parseValue(std::string_view context, SettingKind kind, NumberRange range, SettingChoices choices,
                  const KeyValue& kv) {
  const std::string what = fmt::format("{}: {}", context, kv.key);
  switch (kind) {
    case SettingKind::Whole:
      return parseIntText(what, kv.value, range);
    case SettingKind::Number:
      return parseNumberText(what, kv.value, range);
    case SettingKind::Switch:
      return parseSwitchSetting(context, kv) ? 1.0 : 0.0;
    case SettingKind::Choice:
      for (std::size_t i = 0; i < choices.size(); ++i)
        if (choices[i] == kv.value) return static_cast<double>(i);
      throw Error(ErrorKind::Usage, fmt::format("{}: {}={} must be {}", context, kv.key, kv.value, choicesOf(choices)));
    case SettingKind::Reported:
      break;
  }
  throw Error(ErrorKind::Internal, fmt::format("{}: {} is reported, not set", context, kv.key));
}

std::string formatValue(SettingKind kind, SettingChoices choices, double value) {
  switch (kind) {
    case SettingKind::Whole:
      return fmt::format("{}", static_cast<long long>(value));
    case SettingKind::Switch:
      return value != 0 ? "on" : "off";
    case SettingKind::Choice: {
      const auto index = static_cast<std::size_t>(value);
      // A profile built in code may hold a value no name has: say so rather than guess.
      return value >= 0 && index < choices.size() ? std::string(choices[index]) : std::string("?");
    }
    case SettingKind::Number:
    case SettingKind::Reported:
      break;
  }
  // The shortest text that reads back as the same double.
  return fmt::format("{}", value);
}

void checkRange(std::string_view context, std::string_view key, NumberRange range, double value) {
  if (!(value >= range.min && value <= range.max))
    throw Error(ErrorKind::Usage, fmt::format("{}: {}={} is out of range; give {}", context, key, value,
                                              describeRange(range)));
}

void checkChoice(std::string_view context, std::string_view key, SettingChoices choices, double index) {
  if (!(index >= 0 && index < static_cast<double>(choices.size())))
    throw Error(ErrorKind::Usage,
                fmt::format("{}: {} holds a value that is none of {}", context, key, choicesOf(choices)));
}

}  // namespace settings_detail

std::string settingTakes(const SettingInfo& info) {
  switch (info.kind) {
    case SettingKind::Whole:
    case SettingKind::Number:
      return describeRange(info.range);
    case SettingKind::Switch:
      return "`on` or `off`";
    case SettingKind::Choice: {
      std::vector<std::string> quoted;
      for (std::string_view name : info.choices) quoted.push_back(fmt::format("`{}`", name));
      return choicesOf(quoted);
    }
    case SettingKind::Reported:
      break;
  }
  return "reported";
}

std::string settingsMarkdown(std::span<const SettingInfo> infos) {
  std::string text = "| key | takes | default | why set it |\n|---|---|---|---|\n";
  for (const SettingInfo& info : infos)
    text += fmt::format("| `{}` | {} | `{}` | {} |\n", info.key, settingTakes(info), info.initial, info.help);
  return text;
}

}  // namespace lattice
