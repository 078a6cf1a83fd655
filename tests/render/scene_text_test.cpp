// The scene text is checked before toml++ parses it: invalid UTF-8
// and the characters toml++ 3.3.0's whitespace test mishandles are refused
// with their line and column; comments may hold anything valid.
#include <catch2/catch.hpp>

#include <string>

#include "loader/scene_loader.hpp"
#include "loader/scene_text.hpp"
#include "tests/support/temp_dir.hpp"
#include "foundation/error.hpp"

using namespace lattice;

namespace {
std::string refusal(const std::string& text) {
  try {
    checkSceneText(text, "s.toml");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    return e.what();
  }
  FAIL("the text was accepted: " << text);
  return {};
}
}  // namespace

TEST_CASE("the two-byte scene C2 B6 is refused, located, before toml++ sees it") {
  const std::string pilcrow = "\xC2\xB6";
  CHECK_THAT(refusal(pilcrow), Catch::Contains("s.toml:1:1:") && Catch::Contains("U+00B6") &&
                                   Catch::Contains("\\u00B6"));
  // The same through the file loader, as `lattice render` reads it.
  const lattice::testing::TempDir scratch("scene-text");
  const std::string path = scratch / "pilcrow.toml";
  { std::FILE* f = std::fopen(path.c_str(), "wb"); std::fputs(pilcrow.c_str(), f); std::fclose(f); }
  CHECK_THROWS_WITH(loadScene(path), Catch::Contains(path + ":1:1:") && Catch::Contains("U+00B6"));
}

TEST_CASE("mishandled characters are refused in keys, strings and values, at their place") {
  CHECK_THAT(refusal("a = 1\nb = 2\xC2\xB6\n"), Catch::Contains("s.toml:2:6:"));
  CHECK_THAT(refusal("[t]\n\"\xC3\xA9\" = 1\n"), Catch::Contains("s.toml:2:2:") && Catch::Contains("U+00E9"));
  CHECK_THAT(refusal("x = '\xE3\x80\x81'\n"), Catch::Contains("U+3001"));
  CHECK_THAT(refusal("x = \"\"\"\nab\\\xEF\xBB\xBE\"\"\"\n"), Catch::Contains("U+FEFE"));
  // Each end of every range, and just outside them.
  for (char32_t c : {0xA1u, 0x499u, 0x2C5Eu, 0x2FFFu, 0x3001u, 0x3057u, 0xFB26u, 0xFEFEu})
    CHECK(tomlWhitespaceTestUndefined(c));
  for (char32_t c : {0xA0u, 0x49Au, 0x2C5Du, 0x3000u, 0x3058u, 0xFB25u, 0xFEFFu, 0x2000u})
    CHECK_FALSE(tomlWhitespaceTestUndefined(c));
}

TEST_CASE("comments may hold any character, escapes and other text pass") {
  CHECK_NOTHROW(checkSceneText("# Lewis's th\xC3\xA8se \xC2\xB6 \xE3\x80\x81\na = \"x # \\u00B6\" # \xC2\xB6\n", "s.toml"));
  CHECK_NOTHROW(checkSceneText("a = \"\\\"\" # \xC2\xB6\nb = '''it's''' # \xC3\xA9\n", "s.toml"));
  CHECK_NOTHROW(checkSceneText("name = \"\xE2\x82\xAC \xF0\x9F\x99\x82\"\n", "s.toml"));  // U+20AC, U+1F642
  // A '#' inside a string starts no comment.
  CHECK_THAT(refusal("a = \"# \xC2\xB6\"\n"), Catch::Contains("s.toml:1:8:"));
  CHECK_THAT(refusal("a = \"\"\"\n# \xC2\xB6\n\"\"\"\n"), Catch::Contains("s.toml:2:3:"));
}

TEST_CASE("invalid UTF-8 is refused with its place") {
  CHECK_THAT(refusal("a = 1\n\xFF"), Catch::Contains("s.toml:2:1:") && Catch::Contains("0xFF"));
  CHECK_THAT(refusal("# \xC0\xAF"), Catch::Contains("not valid UTF-8"));        // overlong '/'
  CHECK_THAT(refusal("a = \"\xED\xA0\x80\""), Catch::Contains("s.toml:1:6:"));  // a surrogate
  CHECK_THAT(refusal("a = \"\xE2\x82"), Catch::Contains("not valid UTF-8"));    // cut short
}
