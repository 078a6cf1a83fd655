// The one number parser: every flag, --set value and --at item is read by it,
// so what it refuses is refused everywhere (app/cli/number_flags.hpp).
#include <catch2/catch.hpp>

#include <string>

#include "foundation/error.hpp"
#include "foundation/number_text.hpp"

using lattice::NumberRange;
using lattice::parseIntText;
using lattice::parseNumberText;

namespace {

std::string refusal(std::string_view text, NumberRange range) {
  try {
    (void)parseNumberText("--flag", text, range);
  } catch (const lattice::Error& e) {
    CHECK(e.kind() == lattice::ErrorKind::Usage);
    return e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("NaN, infinities and overflow are refused, naming the flag and the range", "[numbers]") {
  const NumberRange range{0.001, 1e9};
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e999", "-1e999"}) {
    INFO(text);
    const std::string message = refusal(text, range);
    CHECK_THAT(message, Catch::Contains("--flag") && Catch::Contains(text) && Catch::Contains("from 0.001 to 1000000000"));
  }
}

TEST_CASE("malformed text is refused: empty, trailing junk, '+', spaces, hex", "[numbers]") {
  for (const char* text : {"", "12abc", "+5", " 5", "5 ", "0x10", "1,5", "--"}) {
    INFO("'" << text << "'");
    CHECK_THAT(refusal(text, {}), Catch::Contains("is not a finite number"));
  }
}

TEST_CASE("the range and wholeness are checked, values inside pass exactly", "[numbers]") {
  CHECK(parseNumberText("--x", "0.5", {0, 1}) == 0.5);
  CHECK(parseNumberText("--x", "-3", {}) == -3);
  CHECK(parseNumberText("--x", "1e3", {0, 1000}) == 1000);
  CHECK(parseNumberText("--x", "1000", {0, 1000, true}) == 1000);
  for (const char* text : {"1000.5", "1e3", "4.0"}) CHECK_THAT(refusal(text, {0, 2000, true}), Catch::Contains("not a whole number"));
  CHECK_THAT(refusal("100.0001", {0, 100}), Catch::Contains("out of range") && Catch::Contains("from 0 to 100"));
  CHECK_THAT(refusal("-1", {0, 100}), Catch::Contains("out of range"));
}

TEST_CASE("an int setting refuses what an int cannot hold", "[numbers]") {
  CHECK(parseIntText("width", "4096", {}) == 4096);
  CHECK_THROWS_AS(parseIntText("width", "3e9", {}), lattice::Error);
  CHECK_THROWS_AS(parseIntText("width", "1.5", {}), lattice::Error);
  CHECK_THROWS_AS(parseIntText("width", "nan", {}), lattice::Error);
}
