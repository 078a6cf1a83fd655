// The settings schema on a made-up profile: what --set refuses and how it
// says so, describe() in table order and back, presets first, the checks of
// a profile built in code, and the Markdown the docs show.
#include <catch2/catch.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "foundation/byte_count.hpp"
#include "foundation/error.hpp"
#include "foundation/settings_schema.hpp"

using namespace lattice;

namespace {

enum class Shade { Light, Dark };
struct Port {
  int baud = 9600;
};
struct Toy {
  std::string name = "plain";
  int count = 3;
  double speed = 1.5;
  bool fast = false;
  Shade shade = Shade::Dark;
  char separator = ' ';
  Port port;
};

constexpr std::string_view kShades[] = {"light", "dark"};
constexpr std::string_view kSeparatorNames[] = {"space", "comma"};
constexpr char kSeparators[] = {' ', ','};
constexpr std::string_view kPresets[] = {"plain", "busy"};

constexpr Setting<Toy> kRows[] = {
    {"preset", SettingKind::Choice, {}, &choicesIn<kPresets>, "a starting point",
     [](const Toy& t) { return t.name == "busy" ? 1.0 : 0.0; },
     [](Toy& t, double i) {
       t = Toy{};
       if (i != 0) {
         t.name = "busy";
         t.count = 9;
       }
     },
     nullptr, true},
    whole<&Toy::count>("count", {1, 10}, "how many"),
    number<&Toy::speed>("speed", {0.5, 100}, "how fast"),
    reported<Toy>("double-count", [](const Toy& t) { return std::to_string(2 * t.count); }),
    onOff<&Toy::fast>("fast", "hurry"),
    choice<kShades, &Toy::shade>("shade", "the colour"),
    choiceAs<kSeparatorNames, kSeparators, &Toy::separator>("separator", "between things"),
    whole<&Toy::port, &Port::baud>("baud", {50, 1000000}, "the line"),
};

// Across two keys: fast needs at least 2.
void validateToy(const Toy& t) {
  if (t.fast && t.count < 2) throw Error(ErrorKind::Usage, "toy profile: fast needs a count of 2 or more");
}

constexpr SettingsSchema<Toy> kToy{"toy profile", kRows, [] { return Toy{}; }, validateToy};

std::string refusal(Toy& toy, const std::string& keyValue) {
  const std::string before = describeSettings(kToy, toy);
  try {
    applySetting(kToy, toy, keyValue);
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Usage);
    CHECK(describeSettings(kToy, toy) == before);  // a refused setting leaves the profile as it was
    return e.what();
  }
  return "taken";
}

}  // namespace

TEST_CASE("describe() lists every row in table order, reported rows too") {
  CHECK(describeSettings(kToy, Toy{}) ==
        "preset=plain\ncount=3\nspeed=1.5\ndouble-count=6\nfast=off\nshade=dark\nseparator=space\nbaud=9600\n");
}

TEST_CASE("values are parsed by the row's kind and written through its member path") {
  Toy t;
  for (const char* kv : {"count=7", "speed=2.25", "fast=on", "shade=light", "separator=comma", "baud=300"})
    applySetting(kToy, t, kv);
  CHECK(t.count == 7);
  CHECK(t.speed == 2.25);
  CHECK(t.fast);
  CHECK(t.shade == Shade::Light);
  CHECK(t.separator == ',');
  CHECK(t.port.baud == 300);
}

TEST_CASE("NaN, infinities, fractions and values out of range are refused, naming the key and its range") {
  for (const char* bad : {"nan", "inf", "-inf", "1e999", "11", "0", "2.5", "1e1", "", "7x"}) {
    Toy t;
    const std::string message = refusal(t, std::string("count=") + bad);
    INFO(bad << ": " << message);
    CHECK_THAT(message, Catch::StartsWith("toy profile: count: '") && Catch::Contains("a whole number from 1 to 10"));
  }
  for (const char* bad : {"nan", "inf", "-inf", "1e999", "0.25", "101"}) {
    Toy t;
    const std::string message = refusal(t, std::string("speed=") + bad);
    INFO(bad << ": " << message);
    CHECK_THAT(message, Catch::StartsWith("toy profile: speed: '") && Catch::Contains("a number from 0.5 to 100"));
  }
  Toy t;
  CHECK_THAT(refusal(t, "baud=1e400"), Catch::Contains("baud") && Catch::Contains("from 50 to 1000000"));
}

TEST_CASE("names, switches and keys that are not the table's are refused with what it takes") {
  Toy t;
  CHECK(refusal(t, "shade=grey") == "toy profile: shade=grey must be light or dark");
  CHECK(refusal(t, "separator=tab") == "toy profile: separator=tab must be space or comma");
  CHECK_THAT(refusal(t, "fast=nan"), Catch::Contains("'fast=nan' needs on or off"));
  // The keys --set takes: the reported row is not one.
  const std::string keys = "keys: preset, count, speed, fast, shade, separator, baud";
  CHECK(refusal(t, "colour=red") == "toy profile: unknown key 'colour'; " + keys);
  CHECK(refusal(t, "double-count=4") == "toy profile: unknown key 'double-count'; " + keys);
  CHECK_THAT(refusal(t, "count"), Catch::Contains("not key=value") && Catch::EndsWith(keys));
  CHECK(settingKeys(kToy) == "preset, count, speed, fast, shade, separator, baud");
}

TEST_CASE("the schema's validate sees the changed profile and can refuse it") {
  Toy t;
  applySetting(kToy, t, "count=1");
  CHECK(refusal(t, "fast=on") == "toy profile: fast needs a count of 2 or more");
  CHECK_FALSE(t.fast);
}

TEST_CASE("every value describe() shows is taken back unchanged") {
  Toy changed;
  for (const char* kv : {"preset=busy", "speed=0.1e1", "fast=yes", "shade=light", "separator=comma", "baud=50"})
    applySetting(kToy, changed, kv);
  const std::string listing = describeSettings(kToy, changed);
  Toy back;
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < listing.size();) {
    const std::size_t end = listing.find('\n', at);
    const std::string line = listing.substr(at, end - at);
    if (line.rfind("double-count=", 0) != 0) lines.push_back(line);
    at = end + 1;
  }
  applySettings(kToy, back, lines);
  CHECK(describeSettings(kToy, back) == listing);
}

TEST_CASE("a preset is applied before the other keys wherever it is typed") {
  Toy t;
  applySettings(kToy, t, {"count=4", "preset=busy"});
  CHECK(t.name == "busy");
  CHECK(t.count == 4);  // busy's 9, refined
}

TEST_CASE("settingsChanged gives what --set would have to say") {
  Toy to;
  to.fast = true;
  to.port.baud = 1200;
  CHECK(settingsChanged(kToy, Toy{}, to) == std::vector<std::string>{"fast=on", "baud=1200"});
  CHECK(settingsChanged(kToy, to, to).empty());
}

TEST_CASE("a profile built in code is checked against the table") {
  CHECK_NOTHROW(checkSettings(kToy, Toy{}));
  Toy wide;
  wide.count = 11;
  CHECK_THROWS_WITH(checkSettings(kToy, wide),
                    "toy profile: count=11 is out of range; give a whole number from 1 to 10");
  Toy tab;
  tab.separator = '\t';
  CHECK_THROWS_WITH(checkSettings(kToy, tab), "toy profile: separator holds a value that is none of space or comma");
  CHECK(describeSettings(kToy, tab).find("separator=?\n") != std::string::npos);
}

TEST_CASE("the Markdown table: every settable row with what it takes and its default") {
  CHECK(settingsMarkdown(settingInfos(kToy)) ==
        "| key | takes | default | why set it |\n"
        "|---|---|---|---|\n"
        "| `preset` | `plain` or `busy` | `plain` | a starting point |\n"
        "| `count` | a whole number from 1 to 10 | `3` | how many |\n"
        "| `speed` | a number from 0.5 to 100 | `1.5` | how fast |\n"
        "| `fast` | `on` or `off` | `off` | hurry |\n"
        "| `shade` | `light` or `dark` | `dark` | the colour |\n"
        "| `separator` | `space` or `comma` | `space` | between things |\n"
        "| `baud` | a whole number from 50 to 1000000 | `9600` | the line |\n");
}

namespace {

// Settings that may be left unset, and a size in bytes.
struct Budget {
  std::optional<double> seconds;
  std::optional<Shade> shade;
  std::optional<std::uint64_t> limit;
  std::uint64_t cache = std::uint64_t(64) << 20;
};

constexpr Setting<Budget> kBudgetRows[] = {
    orUnset(number<&Budget::seconds>("seconds", {0.001, 1e9}, "how long"), "none"),
    orUnset(choice<kShades, &Budget::shade>("shade", "the colour"), "own"),
    orUnset(bytes<&Budget::limit>("limit", "how many bytes"), "none"),
    bytes<&Budget::cache>("cache", "how much to keep"),
};

constexpr SettingsSchema<Budget> kBudget{"budget", kBudgetRows, [] { return Budget{}; }};

}  // namespace

TEST_CASE("a setting left unset is named by its word, which --set takes back") {
  Budget b;
  CHECK(describeSettings(kBudget, b) == "seconds=none\nshade=own\nlimit=none\ncache=64MiB\n");
  applySetting(kBudget, b, "seconds=60");
  applySetting(kBudget, b, "shade=light");
  applySetting(kBudget, b, "limit=56K");
  CHECK(b.seconds == 60.0);
  CHECK(b.shade == Shade::Light);
  CHECK(b.limit == std::uint64_t(56 * 1024));
  CHECK(describeSettings(kBudget, b) == "seconds=60\nshade=light\nlimit=56KiB\ncache=64MiB\n");
  applySetting(kBudget, b, "seconds=none");
  applySetting(kBudget, b, "shade=own");
  applySetting(kBudget, b, "limit=none");
  CHECK_FALSE(b.seconds.has_value());
  CHECK_FALSE(b.shade.has_value());
  CHECK_FALSE(b.limit.has_value());
  checkSettings(kBudget, b);  // unset is not out of range
}

TEST_CASE("NaN, infinities and bad sizes are refused by a row that may be unset, naming the key") {
  Budget b;
  for (const char* bad : {"seconds=nan", "seconds=inf", "seconds=0", "limit=nan", "limit=0", "limit=-5",
                          "limit=1e400", "limit=12Q", "cache=none", "shade=none"}) {
    INFO(bad);
    const std::string key = std::string(bad).substr(0, std::string(bad).find('='));
    try {
      applySetting(kBudget, b, bad);
      FAIL("taken");
    } catch (const Error& e) {
      CHECK(e.kind() == ErrorKind::Usage);
      CHECK(std::string(e.what()).find(key) != std::string::npos);
    }
  }
  CHECK(describeSettings(kBudget, b) == "seconds=none\nshade=own\nlimit=none\ncache=64MiB\n");
}

TEST_CASE("a size in bytes reads back as the same count, and the docs say what a row takes") {
  for (std::uint64_t n : {std::uint64_t(1), std::uint64_t(57600), std::uint64_t(57344), std::uint64_t(3) << 30,
                          (std::uint64_t(64) << 20) + 1}) {
    INFO(n);
    Budget b;
    applySetting(kBudget, b, "cache=" + byteCountText(n));
    CHECK(b.cache == n);
  }
  const std::vector<SettingInfo> infos = settingInfos(kBudget);
  REQUIRE(infos.size() == 4);
  CHECK(settingTakes(infos[0]) == "a number from 0.001 to 1000000000, or `none`");
  CHECK(settingTakes(infos[1]) == "`light`, `dark` or `own`");
  CHECK(settingTakes(infos[3]) == "a size in bytes (57600, 56K, 8MiB)");
}
