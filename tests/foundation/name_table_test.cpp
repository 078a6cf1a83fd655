// foundation/name_table.hpp: the one way enum names are listed, found and
// spelled in messages, over the tables the stages keep.
#include <catch2/catch.hpp>

#include <array>

#include "foundation/little_endian.hpp"
#include "foundation/name_table.hpp"

using namespace lattice;

namespace {
enum class Tint { Red = 3, Green = 5, Blue = 9 };
constexpr std::array<EnumName<Tint>, 3> kTints = {{{Tint::Red, "red"}, {Tint::Green, "green"}, {Tint::Blue, "blue"}}};
struct Preset {
  std::string name;
  int value;
};
}  // namespace

TEST_CASE("name tables: lists, sentences, look-ups both ways and file codes") {
  CHECK(namesOf(kTints) == "red, green, blue");
  CHECK(choicesOf(kTints) == "red, green or blue");
  CHECK(nameList(kTints) == std::vector<std::string>{"red", "green", "blue"});
  CHECK(valueNamed(kTints, "green") == Tint::Green);
  CHECK_FALSE(valueNamed(kTints, "Green").has_value());
  CHECK(nameOfValue(kTints, Tint::Blue) == "blue");
  CHECK(nameOfValue(kTints, static_cast<Tint>(4), "?") == "?");
  CHECK(valueWithCode(kTints, 9) == Tint::Blue);
  CHECK_FALSE(valueWithCode(kTints, 4).has_value());
  const std::array<EnumName<Tint>, 1> one = {{{Tint::Red, "red"}}};
  CHECK(choicesOf(one) == "red");
  const std::vector<Preset> presets{{"strict", 1}, {"compact", 2}};
  CHECK(choicesOf(presets) == "strict or compact");
  REQUIRE(findNamed(presets, "compact") != nullptr);
  CHECK(findNamed(presets, "compact")->value == 2);
  // A plain list of names is a table too.
  const std::vector<std::string_view> plain{"hashed", "compressed"};
  CHECK(choicesOf(plain) == "hashed or compressed");
  CHECK(namesOf(plain) == "hashed, compressed");
  CHECK(findNamed(plain, "compressed") == &plain[1]);
  CHECK(findNamed(plain, "chained") == nullptr);
}

TEST_CASE("little-endian fields: least significant byte first, and back") {
  std::vector<std::uint8_t> out;
  appendLittleEndian(out, 0x0102030405060708ull, 8);
  appendLittleEndian(out, 0xABCD, 2);
  CHECK(out == std::vector<std::uint8_t>{8, 7, 6, 5, 4, 3, 2, 1, 0xCD, 0xAB});
  CHECK(readLittleEndian(out.data(), 8) == 0x0102030405060708ull);
  CHECK(readLittleEndian(out.data() + 8, 2) == 0xABCD);
  CHECK(readLittleEndian(out.data(), 3) == 0x060708);
}
