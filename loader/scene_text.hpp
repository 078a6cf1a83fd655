#pragma once
// Checks on a scene file's text before the TOML parser sees it (docs/limits.md, "toml++").
//
// Method and why: Debian's toml++ 3.3.0 has undefined behaviour in its
// Unicode whitespace test (is_non_ascii_horizontal_whitespace reaches
// TOML_UNREACHABLE for U+00A1..U+0499, U+2C5E..U+2FFF, U+3001..U+3057 and
// U+FB26..U+FEFE; the two-byte file C2 B6, a pilcrow, reaches it). The parser
// asks that test of every character of keys, after values and at the start
// of lines, but not inside comments or string values. So the text is decoded
// as UTF-8 (invalid UTF-8 is refused here with its line and column), a small
// lexer follows TOML's comments and four string forms, and those characters
// are refused outside comments, located, with the fix: a \uXXXX escape in a
// "basic string" means the same and never reaches the test. Strings are
// refused too because a quoted key is a string and telling keys from values
// would need the whole grammar; an escape works in both.
//
// Tunables: kMaxSceneBytes, the largest scene file read (16 MiB; the largest
// example scene is 3 KB and a 100,000-point polyline about 3 MB).
#include <cstdint>
#include <string>
#include <string_view>

namespace lattice {

inline constexpr std::uint64_t kMaxSceneBytes = std::uint64_t(16) << 20;

// True for the code points toml++ 3.3.0's whitespace test mishandles.
bool tomlWhitespaceTestUndefined(char32_t c);

// Error(Input) "file:line:column: ..." for invalid UTF-8 or a mishandled
// character outside a comment; returns when the text is safe to parse.
void checkSceneText(std::string_view text, const std::string& file);

// The scene file's bytes: Error(Input) when it cannot be read or is larger
// than kMaxSceneBytes (checked from its size before reading).
std::string readSceneText(const std::string& file);

}  // namespace lattice
