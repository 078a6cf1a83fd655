// Every device's --set keys, as its settings table declares them: each one
// is in the device's describe() listing, each value a listing shows is taken
// back unchanged, and NaN, infinities, values out of range and unknown keys
// are refused with the key and what it takes.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "devices/device_table.hpp"
#include "foundation/error.hpp"

using namespace lattice;

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\n', at);
    out.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

// The lines of a listing that --set takes (reported lines left out).
std::vector<std::string> settableLines(const std::string& listing, const std::vector<SettingInfo>& infos) {
  std::vector<std::string> out;
  for (const std::string& line : lines(listing))
    for (const SettingInfo& info : infos)
      if (line.rfind(std::string(info.key) + "=", 0) == 0) out.push_back(line);
  return out;
}

std::string refusal(std::string_view device, const std::string& keyValue) {
  try {
    (void)devices::makeDevice(device, {keyValue});
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Usage);
    return e.what();
  }
  return "taken";
}

// Values worth trying for a key besides its default: its range's ends, or its names.
std::vector<std::string> valuesOf(const SettingInfo& info) {
  switch (info.kind) {
    case SettingKind::Whole:
    case SettingKind::Number: {
      std::vector<std::string> v{fmt::format("{}", info.range.min)};
      v.push_back(fmt::format("{}", info.range.max < 1e9 ? info.range.max : info.range.min + 1));
      return v;
    }
    case SettingKind::Bytes:
      return {"1", "56K", "8MiB"};
    case SettingKind::Switch:
      return {"on", "off"};
    case SettingKind::Choice:
      return {info.choices.begin(), info.choices.end()};
    case SettingKind::Reported:
      break;
  }
  return {};
}

}  // namespace

TEST_CASE("every device declares settings, each with a help line") {
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    INFO(entry.name);
    const std::vector<SettingInfo> infos = entry.settings();
    CHECK_FALSE(infos.empty());
    for (const SettingInfo& info : infos) {
      INFO(info.key);
      CHECK(info.help.size() > 10);
      CHECK(info.help.find('|') == std::string_view::npos);  // a Markdown table cell
    }
  }
}

TEST_CASE("every key of a device's table is in its describe() listing, with its default") {
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    INFO(entry.name);
    const std::vector<std::string> listing = lines(devices::makeDevice(entry.name).profileText);
    for (const SettingInfo& info : entry.settings()) {
      const std::string line = fmt::format("{}={}", info.key, info.initial);
      INFO(line);
      CHECK(std::count(listing.begin(), listing.end(), line) == 1);
    }
  }
}

TEST_CASE("each value a listing shows is taken back unchanged, for every key's range ends and names") {
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    INFO(entry.name);
    const std::vector<SettingInfo> infos = entry.settings();
    int tried = 0;
    for (const SettingInfo& info : infos) {
      for (const std::string& value : valuesOf(info)) {
        const std::string setting = fmt::format("{}={}", info.key, value);
        INFO(setting);
        std::string listing;
        try {
          listing = devices::makeDevice(entry.name, {setting}).profileText;
        } catch (const Error&) {
          continue;  // refused by a constraint over several keys (reserved with few planes)
        }
        const std::string back = devices::makeDevice(entry.name, settableLines(listing, infos)).profileText;
        CHECK(back == listing);
        ++tried;
      }
    }
    CHECK(tried >= static_cast<int>(infos.size()));
  }
}

TEST_CASE("NaN, infinities and values out of range are refused for every numeric key, naming the key and range") {
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    INFO(entry.name);
    for (const SettingInfo& info : entry.settings()) {
      const std::vector<std::string> bad =
          info.kind == SettingKind::Whole || info.kind == SettingKind::Number
              ? std::vector<std::string>{"nan", "inf", "-inf", "1e999", fmt::format("{}", info.range.min - 1)}
              : std::vector<std::string>{"nan", "inf"};
      for (const std::string& value : bad) {
        const std::string message = refusal(entry.name, fmt::format("{}={}", info.key, value));
        INFO(info.key << "=" << value << ": " << message);
        CHECK_THAT(message, Catch::Contains(std::string(info.key)));
        if (info.kind == SettingKind::Whole || info.kind == SettingKind::Number)
          CHECK_THAT(message, Catch::Contains(describeRange(info.range)));
        if (info.kind == SettingKind::Choice)
          for (std::string_view name : info.choices) CHECK_THAT(message, Catch::Contains(std::string(name)));
      }
    }
  }
}

TEST_CASE("an unknown key is refused with the device's keys") {
  for (const devices::DeviceEntry& entry : devices::deviceTable()) {
    INFO(entry.name);
    std::string keys;
    for (const SettingInfo& info : entry.settings()) keys += (keys.empty() ? "" : ", ") + std::string(info.key);
    CHECK_THAT(refusal(entry.name, "no-such-key=1"), Catch::EndsWith("unknown key 'no-such-key'; keys: " + keys));
    CHECK_THAT(refusal(entry.name, "no-equals"), Catch::EndsWith("keys: " + keys));
  }
}
