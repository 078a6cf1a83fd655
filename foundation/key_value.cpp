#include "foundation/key_value.hpp"

#include <fmt/format.h>

#include <string>

#include "foundation/error.hpp"
#include "foundation/number_text.hpp"

namespace lattice {

KeyValue splitKeyValue(std::string_view context, std::string_view text, std::string_view keys) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw Error(ErrorKind::Usage, fmt::format("{}: '{}' is not key=value; keys: {}", context, text, keys));
  return {text.substr(0, eq), text.substr(eq + 1)};
}

// Both go through the one number parser (foundation/number_text.hpp); the
// profile's validate() then checks the value against its own range.
int parseIntSetting(std::string_view context, const KeyValue& kv) {
  return parseIntText(fmt::format("{}: {}", context, kv.key), kv.value, {});
}

double parseNumberSetting(std::string_view context, const KeyValue& kv) {
  return parseNumberText(fmt::format("{}: {}", context, kv.key), kv.value, {});
}

bool parseSwitchSetting(std::string_view context, const KeyValue& kv) {
  const std::string_view t = kv.value;
  if (t == "on" || t == "yes" || t == "true" || t == "1") return true;
  if (t == "off" || t == "no" || t == "false" || t == "0") return false;
  throw Error(ErrorKind::Usage, fmt::format("{}: '{}={}' needs on or off", context, kv.key, kv.value));
}

void unknownSetting(std::string_view context, const KeyValue& kv, std::string_view keys) {
  throw Error(ErrorKind::Usage, fmt::format("{}: unknown key '{}'; keys: {}", context, kv.key, keys));
}

}  // namespace lattice
