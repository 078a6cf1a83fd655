#pragma once
// "key=value" settings, as device profiles take them from `--set`. Errors are
// lattice::Error(Usage) that name the context ("tek4125 profile"), the bad
// text and a corrected example, and list the accepted keys.
#include <string_view>

namespace lattice {

struct KeyValue {
  std::string_view key;
  std::string_view value;
};

// Splits at the first '='; `keys` is the list shown when the text is not key=value.
KeyValue splitKeyValue(std::string_view context, std::string_view text, std::string_view keys);
int parseIntSetting(std::string_view context, const KeyValue& kv);
double parseNumberSetting(std::string_view context, const KeyValue& kv);
bool parseSwitchSetting(std::string_view context, const KeyValue& kv);  // on/off, yes/no, true/false, 1/0
[[noreturn]] void unknownSetting(std::string_view context, const KeyValue& kv, std::string_view keys);

}  // namespace lattice
