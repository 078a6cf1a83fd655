#include "loader/scene_text.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "foundation/error.hpp"

namespace lattice {
namespace {

// One decoded code point and its length in bytes; length 0 for invalid UTF-8
// (overlong forms, surrogates, beyond U+10FFFF, cut-off sequences).
struct Decoded {
  char32_t c = 0;
  std::size_t length = 0;
};

Decoded decode(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[at + i]); };
  const unsigned char b0 = byte(0);
  if (b0 < 0x80) return {b0, 1};
  std::size_t n = 0;
  char32_t c = 0, least = 0;
  if ((b0 & 0xE0) == 0xC0) n = 2, c = b0 & 0x1F, least = 0x80;
  else if ((b0 & 0xF0) == 0xE0) n = 3, c = b0 & 0x0F, least = 0x800;
  else if ((b0 & 0xF8) == 0xF0) n = 4, c = b0 & 0x07, least = 0x10000;
  else return {};
  if (at + n > text.size()) return {};
  for (std::size_t i = 1; i < n; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return {};
    c = c << 6 | (byte(i) & 0x3F);
  }
  if (c < least || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return {};
  return {c, n};
}

enum class Lex { Normal, Comment, Basic, MultiBasic, Literal, MultiLiteral };

std::size_t runOf(std::string_view text, std::size_t at, char quote) {
  std::size_t n = 0;
  while (at + n < text.size() && text[at + n] == quote) ++n;
  return n;
}

}  // namespace

bool tomlWhitespaceTestUndefined(char32_t c) {
  return (c >= 0xA1 && c <= 0x499) || (c >= 0x2C5E && c <= 0x2FFF) || (c >= 0x3001 && c <= 0x3057) ||
         (c >= 0xFB26 && c <= 0xFEFE);
}

void checkSceneText(std::string_view text, const std::string& file) {
  Lex lex = Lex::Normal;
  long line = 1, column = 1;
  std::size_t at = 0;
  // Advances past n code points of ASCII (quotes, backslashes).
  auto skipAscii = [&](std::size_t n) {
    at += n;
    column += static_cast<long>(n);
  };
  while (at < text.size()) {
    const Decoded d = decode(text, at);
    if (d.length == 0)
      throw Error(ErrorKind::Input,
                  locate(file, line, column,
                         fmt::format("not valid UTF-8 (byte 0x{:02X}); scene files are UTF-8 text",
                                     static_cast<unsigned char>(text[at]))));
    if (lex != Lex::Comment && tomlWhitespaceTestUndefined(d.c))
      throw Error(ErrorKind::Input,
                  locate(file, line, column,
                         fmt::format("the character U+{0:04X} is refused outside comments: the TOML library used "
                                     "(toml++ 3.3.0) mishandles U+00A1..U+0499, U+2C5E..U+2FFF, U+3001..U+3057 and "
                                     "U+FB26..U+FEFE there; in a \"double-quoted\" string write it as \\u{0:04X} "
                                     "(docs/scene-format.md)",
                                     static_cast<std::uint32_t>(d.c))));
    const char ch = d.length == 1 ? static_cast<char>(d.c) : '\0';
    if (ch == '\n') {
      ++line;
      column = 1;
      at += 1;
      if (lex == Lex::Comment || lex == Lex::Basic || lex == Lex::Literal) lex = Lex::Normal;
      continue;
    }
    switch (lex) {
      case Lex::Normal:
        if (ch == '#') {
          lex = Lex::Comment;
        } else if (ch == '"' || ch == '\'') {
          const bool multi = runOf(text, at, ch) >= 3;
          lex = ch == '"' ? (multi ? Lex::MultiBasic : Lex::Basic) : (multi ? Lex::MultiLiteral : Lex::Literal);
          skipAscii(multi ? 3 : 1);
          continue;
        }
        break;
      case Lex::Comment: break;
      case Lex::Basic:
      case Lex::MultiBasic:
        if (ch == '\\' && at + 1 < text.size() && text[at + 1] != '\n') {
          // An escape: the next code point is taken as it is (\" does not end
          // the string). A line-ending backslash leaves the newline to be counted.
          const Decoded next = decode(text, at + 1);
          if (next.length == 0) {
            skipAscii(1);
            continue;  // reported as invalid UTF-8 at the next step
          }
          if (next.length == 1 && next.c == '\r') {
            skipAscii(1);
            continue;
          }
          if (tomlWhitespaceTestUndefined(next.c)) {
            skipAscii(1);
            continue;  // reported at the next step
          }
          at += 1 + next.length;
          column += 2;
          continue;
        }
        if (ch == '"') {
          if (lex == Lex::Basic) {
            lex = Lex::Normal;
          } else if (const std::size_t run = runOf(text, at, '"'); run >= 3) {
            lex = Lex::Normal;
            skipAscii(run);
            continue;
          }
        }
        break;
      case Lex::Literal:
        if (ch == '\'') lex = Lex::Normal;
        break;
      case Lex::MultiLiteral:
        if (ch == '\'') {
          if (const std::size_t run = runOf(text, at, '\''); run >= 3) {
            lex = Lex::Normal;
            skipAscii(run);
            continue;
          }
        }
        break;
    }
    at += d.length;
    column += 1;
  }
}

std::string readSceneText(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw Error(ErrorKind::Input,
                fmt::format("{}: cannot read the scene file (no such file, or not a regular file)", file));
  const std::uint64_t size = std::filesystem::file_size(file, ec);
  if (ec) throw Error(ErrorKind::Input, fmt::format("{}: cannot read the scene file: {}", file, ec.message()));
  if (size > kMaxSceneBytes)
    throw Error(ErrorKind::Input, fmt::format("{}: {} bytes; scene files may be at most {} bytes (kMaxSceneBytes, "
                                              "docs/limits.md)",
                                              file, size, kMaxSceneBytes));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot open: {}", file, std::strerror(errno)));
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(in.gcount()));  // a file that shrank meanwhile
  return text;
}

}  // namespace lattice
