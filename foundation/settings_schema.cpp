#include "foundation/settings_schema.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

#include "foundation/byte_count.hpp"
#include "foundation/error.hpp"
#include "foundation/name_table.hpp"

namespace lattice {
namespace settings_detail {

double parseValue(std::string_view context, const RowType& type, const KeyValue& kv) {
  const std::string what = fmt::format("{}: {}", context, kv.key);
  if (!type.unset.empty() && kv.value == type.unset) return std::numeric_limits<double>::quiet_NaN();
  switch (type.kind) {
    case SettingKind::Whole:
      return parseIntText(what, kv.value, type.range);
    case SettingKind::Number:
      return parseNumberText(what, kv.value, type.range);
    case SettingKind::Bytes:
      return static_cast<double>(parseByteCount(kv.value, what));
    case SettingKind::Switch:
      return parseSwitchSetting(context, kv) ? 1.0 : 0.0;
    case SettingKind::Choice:
      for (std::size_t i = 0; i < type.choices.size(); ++i)
        if (type.choices[i] == kv.value) return static_cast<double>(i);
      throw Error(ErrorKind::Usage, fmt::format("{}: {}={} must be {}{}{}", context, kv.key, kv.value,
                                                choicesOf(type.choices), type.unset.empty() ? "" : ", or ",
                                                type.unset));
    case SettingKind::Reported:
      break;
  }
  throw Error(ErrorKind::Internal, fmt::format("{}: {} is reported, not set", context, kv.key));
}

std::string formatValue(const RowType& type, double value) {
  if (!type.unset.empty() && std::isnan(value)) return std::string(type.unset);
  switch (type.kind) {
    case SettingKind::Whole:
      return fmt::format("{}", static_cast<long long>(value));
    case SettingKind::Bytes:
      return byteCountText(static_cast<std::uint64_t>(value));
    case SettingKind::Switch:
      return value != 0 ? "on" : "off";
    case SettingKind::Choice: {
      const auto index = static_cast<std::size_t>(value);
      // A profile built in code may hold a value no name has: say so rather than guess.
      return value >= 0 && index < type.choices.size() ? std::string(type.choices[index]) : std::string("?");
    }
    case SettingKind::Number:
    case SettingKind::Reported:
      break;
  }
  // The shortest text that reads back as the same double.
  return fmt::format("{}", value);
}

void checkRange(std::string_view context, std::string_view key, const RowType& type, double value) {
  if (!type.unset.empty() && std::isnan(value)) return;
  if (!(value >= type.range.min && value <= type.range.max))
    throw Error(ErrorKind::Usage, fmt::format("{}: {}={} is out of range; give {}", context, key, value,
                                              describeRange(type.range)));
}

void checkChoice(std::string_view context, std::string_view key, SettingChoices choices, double index) {
  if (!(index >= 0 && index < static_cast<double>(choices.size())))
    throw Error(ErrorKind::Usage,
                fmt::format("{}: {} holds a value that is none of {}", context, key, choicesOf(choices)));
}

}  // namespace settings_detail

std::string settingTakes(const SettingInfo& info) {
  std::string takes;
  switch (info.kind) {
    case SettingKind::Whole:
    case SettingKind::Number:
      takes = describeRange(info.range);
      break;
    case SettingKind::Bytes:
      takes = "a size in bytes (57600, 56K, 8MiB)";
      break;
    case SettingKind::Switch:
      takes = "`on` or `off`";
      break;
    case SettingKind::Choice: {
      std::vector<std::string> quoted;
      for (std::string_view name : info.choices) quoted.push_back(fmt::format("`{}`", name));
      if (!info.unset.empty()) quoted.push_back(fmt::format("`{}`", info.unset));
      return choicesOf(quoted);
    }
    case SettingKind::Reported:
      return "reported";
  }
  if (!info.unset.empty()) takes += fmt::format(", or `{}`", info.unset);
  return takes;
}

std::string settingsMarkdown(std::span<const SettingInfo> infos) {
  std::string text = "| key | takes | default | why set it |\n|---|---|---|---|\n";
  for (const SettingInfo& info : infos)
    text += fmt::format("| `{}` | {} | `{}` | {} |\n", info.key, settingTakes(info), info.initial, info.help);
  return text;
}

}  // namespace lattice
