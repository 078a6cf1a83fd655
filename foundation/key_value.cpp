#include "foundation/key_value.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

#include "foundation/error.hpp"

namespace lattice {

KeyValue splitKeyValue(std::string_view context, std::string_view text, std::string_view keys) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw Error(ErrorKind::Usage, fmt::format("{}: '{}' is not key=value; keys: {}", context, text, keys));
  return {text.substr(0, eq), text.substr(eq + 1)};
}

int parseIntSetting(std::string_view context, const KeyValue& kv) {
  int v = 0;
  auto [end, ec] = std::from_chars(kv.value.data(), kv.value.data() + kv.value.size(), v);
  if (kv.value.empty() || ec != std::errc() || end != kv.value.data() + kv.value.size())
    throw Error(ErrorKind::Usage,
                fmt::format("{}: '{}={}' needs a whole number, e.g. {}=8", context, kv.key, kv.value, kv.key));
  return v;
}

double parseNumberSetting(std::string_view context, const KeyValue& kv) {
  std::string text(kv.value);
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(v))
    throw Error(ErrorKind::Usage,
                fmt::format("{}: '{}={}' needs a finite number, e.g. {}=400", context, kv.key, kv.value, kv.key));
  return v;
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
