// The 4027 command language as the emulator reads it: terminators,
// separators, case, !COM, and every kind of bad number.
#include <catch2/catch.hpp>

#include <string>
#include <string_view>

#include "devices/tek4027/tek4027_decoder.hpp"

using namespace lattice;
using namespace lattice::tek4027;

namespace {

Tek4027Decoder decode(std::string_view text, Tek4027Profile profile = {}) {
  Tek4027Decoder d(profile);
  d.feed(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  d.finish();
  return d;
}

// Pot at terminal coordinates (origin lower left).
int potAt(const Tek4027Decoder& d, int x, int yUp) { return d.image().at(x, d.image().height - 1 - yUp); }

}  // namespace

TEST_CASE("a vector is drawn in the selected pot, origin at the lower left") {
  auto d = decode("!COL C3\r!VEC 10 0 14 0\r");
  CHECK(d.report().commands == 2);
  CHECK(d.report().malformed == 0);
  for (int x = 10; x <= 14; ++x) CHECK(potAt(d, x, 0) == 3);
  CHECK(potAt(d, 9, 0) == 0);
  CHECK(potAt(d, 15, 0) == 0);
  CHECK(potAt(d, 10, 1) == 0);
  CHECK(d.beamX() == 14);
}

TEST_CASE("every terminator ends a command: CR, semicolon, the next command character") {
  for (std::string_view text : {"!COL C2\r!VEC 1 1 3 1\r", "!COL C2;!VEC 1 1 3 1;", "!COL C2!VEC 1 1 3 1;",
                                "!COL C2\r\n!VEC 1 1 3 1\r\n"}) {
    auto d = decode(text);
    INFO(text);
    CHECK(d.report().commands == 2);
    CHECK(d.report().malformed == 0);
    CHECK(potAt(d, 2, 1) == 2);
  }
}

TEST_CASE("spaces, commas and mixtures separate arguments") {
  for (std::string_view text : {"!VEC 5 6 8 6;", "!VEC 5,6,8,6;", "!VEC 5, 6 ,8 ,6;", "!VEC   5  6\t8 6;"}) {
    auto d = decode(text);
    INFO(text);
    CHECK(d.report().commands == 1);
    CHECK(potAt(d, 5, 6) == 1);
    CHECK(potAt(d, 8, 6) == 1);
    CHECK(potAt(d, 9, 6) == 0);
  }
}

TEST_CASE("command names and pot names are case-insensitive, longer names keep three letters") {
  auto d = decode("!col c4;!vec 2 2 2 4;!VECTOR 7 7 7 7;!Map C4 120 50 100;");
  CHECK(d.report().commands == 4);
  CHECK(d.report().unknownCommands == 0);
  CHECK(potAt(d, 2, 3) == 4);
  CHECK(potAt(d, 7, 7) == 4);
  CHECK(d.image().colormap[4] == Rgb8{255, 0, 0});
}

TEST_CASE("!COM changes the command character and the old one becomes text") {
  auto d = decode("!COM 31;\x1f" "COL C5;\x1fVEC 0 0 3 0;!VEC 0 5 3 5;");
  CHECK(d.commandChar() == '\x1f');
  CHECK(d.report().commands == 3);
  CHECK(potAt(d, 2, 0) == 5);
  CHECK(potAt(d, 2, 5) == 0);        // "!VEC ..." is now workspace text
  CHECK(d.report().malformed == 5);  // ... five stray words, one count each

  auto bad = decode("!COM 65;!COM 32;!COM 0;!COM 59;!COM x;!COM 9;!COM 17;!COM 127;!COM;!COM 31 32;");
  CHECK(bad.commandChar() == '!');
  CHECK(bad.report().malformed == 10);
}

TEST_CASE("relative vectors continue from the beam") {
  auto d = decode("!VEC 10 10 12 10;!RVE 0 -1 -2 0;");
  CHECK(d.report().commands == 2);
  CHECK(potAt(d, 12, 9) == 1);
  CHECK(potAt(d, 10, 9) == 1);
  CHECK(potAt(d, 13, 9) == 0);
  CHECK(d.beamX() == 10);
  CHECK(d.beamY() == 9);
}

TEST_CASE("a polyline connects its points and a lone point is a dot") {
  auto d = decode("!VEC 0 0 0 3 3 3;!VEC 20 20;");
  CHECK(potAt(d, 0, 2) == 1);
  CHECK(potAt(d, 2, 3) == 1);
  CHECK(potAt(d, 1, 1) == 0);
  CHECK(potAt(d, 20, 20) == 1);
  CHECK(potAt(d, 21, 20) == 0);
}

TEST_CASE("a diagonal vector lights one pixel per step, both ends included") {
  auto d = decode("!VEC 0 0 4 2;");
  int lit = 0;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) lit += potAt(d, x, y) == 1;
  CHECK(lit == 5);
  CHECK(potAt(d, 0, 0) == 1);
  CHECK(potAt(d, 4, 2) == 1);
}

TEST_CASE("malformed numbers reject the whole command and are counted") {
  for (std::string_view text : {"!VEC 12a 0 14 0;", "!VEC --3 0 14 0;", "!VEC 1 0 99999999999999999999 0;",
                                "!VEC 1 0 40000 0;", "!VEC 1 0 14;", "!VEC;", "!VEC - 0 3 0;", "!VEC +-1 0 3 0;",
                                "!COL;", "!COL C9;", "!COL 3;", "!COL C1 C2;", "!MAP C1 0 50;", "!MAP C1 0 150 50;",
                                "!MAP X1 0 50 50;", "!MIX C1 101 0 0;", "!ERA Q;", "!LIN;", "!GRA 1;",
                                "!WOR -2;", "!VEC 1 0 2 0 3 0 4 0 5 0 6 0 7 0 8 0 9 0 10 0 11 0 12 0 1234567890123456789012345;"}) {
    auto d = decode(text);
    INFO(text);
    CHECK(d.report().malformed == 1);
    CHECK(d.report().commands == 0);
    for (int x = 0; x < 20; ++x) CHECK(potAt(d, x, 0) == 0);
    CHECK(d.currentPot() == 1);
  }
}

TEST_CASE("large but legal coordinates are clipped, not wrapped") {
  auto d = decode("!VEC -32000 3 32000 3;!RVE 32767 32767 32767 32767 32767 32767;!VEC 650 5 700 5;");
  CHECK(d.report().malformed == 0);
  CHECK(potAt(d, 0, 3) == 1);
  CHECK(potAt(d, 639, 3) == 1);
  CHECK(d.beamX() == 700);
  for (int x = 0; x < 640; ++x) REQUIRE(potAt(d, x, 5) == 0);
  auto far = decode("!VEC 32767 32767;!RVE 32767 32767 32767 32767 32767 32767;");
  CHECK(far.beamX() == Tek4027Decoder::kMaxCoordinate);
}

TEST_CASE("unknown commands are skipped, counted by name, and resynchronise") {
  auto d = decode("!FOO 1 2 3;!ZAPP 5!FOO;!COL C2;!VEC 0 0 1 0;");
  CHECK(d.report().unknownCommands == 3);
  CHECK(d.report().unknownByName.at("FOO") == 2);
  CHECK(d.report().unknownByName.at("ZAPP") == 1);
  CHECK(d.report().commands == 2);
  CHECK(potAt(d, 1, 0) == 2);
}

TEST_CASE("set-up commands are accepted and leave the picture alone") {
  auto d = decode("!WOR 34;!GRA 1,34;!GRA 1 34 1 80;!MON 5 H;!MON 3;!LIN 2;!CLE;!ERA W;!ERA;");
  CHECK(d.report().commands == 9);
  CHECK(d.report().malformed == 0);
  CHECK(d.lineStyle() == 2);
  for (auto p : d.image().pixels) REQUIRE(p == 0);
}

TEST_CASE("!MAP and !MIX define pots and !ERA G clears to the background pot") {
  auto d = decode("!MAP C0 0 50 100 C2 240 50 100;!MIX C3 100 0 100;!VEC 1 1 2 1;!ERA G;");
  CHECK(d.report().commands == 4);
  CHECK(d.image().colormap[0] == Rgb8{0, 0, 255});
  CHECK(d.image().colormap[2] == Rgb8{0, 255, 0});
  CHECK(d.image().colormap[3] == Rgb8{255, 0, 255});
  CHECK(potAt(d, 1, 1) == 0);
  CHECK(d.potHls()[2] == Hls{240, 50, 100});
}

TEST_CASE("text, truncation and stray bytes are counted, never drawn") {
  auto d = decode("hello world\r!COL C2;!VEC 0 0 5");
  CHECK(d.report().malformed == 3);  // "hello", "world", the cut-off vector
  CHECK(d.report().commands == 1);
  CHECK(potAt(d, 0, 0) == 0);
  CHECK(decode("!").report().malformed == 1);
  CHECK(decode("!;!!").report().malformed == 3);
  auto filler = decode("\x11\x13 ; \r\n\x7f");
  CHECK(filler.report().malformed == 0);
}

TEST_CASE("hostile lengths are capped") {
  std::string longName = "!" + std::string(100, 'A') + " 1;";
  CHECK(decode(longName).report().malformed == 1);
  std::string manyArgs = "!VEC";
  for (int i = 0; i < 5000; ++i) manyArgs += " 1 1";
  manyArgs += ";";
  auto d = decode(manyArgs);
  CHECK(d.report().malformed == 1);
  CHECK(potAt(d, 1, 1) == 0);
}

// Forms real programs sent (docs/tek-sources.md, "Tek 4027"), re-typed here
// as the bytes they put on the line.
TEST_CASE("real producers' set-up forms are accepted: !MON n H K, !WOR 33h, !REP") {
  // A Fortran plotting program: bottom 12 lines for text, graphics in 1..22.
  auto d = decode("!MON 12 H K\r!GRA 1 22 1 80\r");
  CHECK(d.report().commands == 2);
  CHECK(d.report().malformed == 0);
  // ncurses terminfo: `wor 33h`, `mon h`, `wor 0`, lower case.
  d = decode("!wor 33h\r!mon h\r!wor 0\r!mon 17\r");
  CHECK(d.report().commands == 4);
  CHECK(d.report().malformed == 0);
  // UGS's pacing request; the emulator has no one to answer, it just accepts it.
  d = decode("!REP 00\r!REP\r");
  CHECK(d.report().commands == 2);
  CHECK(d.report().malformed == 0);
  // Still refused: a flag in the count's place, a word, too many arguments.
  CHECK(decode("!MON 12 HK\r").report().malformed == 1);
  CHECK(decode("!WOR 3x3\r").report().malformed == 1);
  CHECK(decode("!MON 12 H K H\r").report().malformed == 1);
}

TEST_CASE("real producers' drawing forms draw: padded !MIX, trailing commas, !rve") {
  // Fortran i3/i4 fields: numbers padded with spaces after commas, a pot
  // defined by !MIX, a polyline ended by a trailing comma and the next !VEC.
  auto d = decode("!MIX C3 100, 50,  0\r!COL C3\r!VEC   10,   5,  20,   5,!VEC   20,   5,  20,  15\r");
  CHECK(d.report().malformed == 0);
  CHECK(d.report().commands == 4);
  CHECK(d.image().colormap[3] == Rgb8{255, 128, 0});
  for (int x = 10; x <= 20; ++x) CHECK(potAt(d, x, 5) == 3);
  for (int y = 5; y <= 15; ++y) CHECK(potAt(d, 20, y) == 3);
  // A font tool: a dot as a zero-length !vec, then a box by relative steps
  // from the beam (the first step zero), in lower case with commas.
  d = decode("!col c4\r!vec 40,10,40,10\r!rve 0,0,0,6,-4,0,0,-6\r");
  CHECK(d.report().malformed == 0);
  for (int y = 10; y <= 16; ++y) {
    CHECK(potAt(d, 40, y) == 4);
    CHECK(potAt(d, 36, y) == 4);
  }
  for (int x = 36; x <= 40; ++x) CHECK(potAt(d, x, 16) == 4);
  CHECK(d.beamX() == 36);
  CHECK(d.beamY() == 10);
}

TEST_CASE("terminfo's text and set-up commands are known and draw nothing") {
  // ncurses tek4025a reset string: !COM 29 switches to GS, then commands end
  // only where the next one starts, the last at `;`.
  const std::string rs2 = "!com 29\x1d" "del 0\x1drss t\x1d" "buf\x1d" "buf n\x1d" "cle\x1d" "dis\x1d" "dup\x1d"
                          "ech r\x1d" "eol\x1d" "era g\x1d" "for n\x1dpad 203\x1dpad 209\x1dsno n"
                          "\x1dsto 9 17 25 33 41 49 57 65 73\x1dwor 0;";
  auto d = decode(rs2);
  CHECK(d.report().unknownCommands == 0);
  CHECK(d.report().malformed == 0);
  CHECK(d.report().commands == 17);
  CHECK(d.commandChar() == '\x1d');
  // Cursor motion from the tek4025-cr entry and the tek4024 entry.
  d = decode("!jum5,10;!lef 3\r!rig\r!up 2\r!dow 4\r!dli 2\r!ili\r!dch\r!att e\r");
  CHECK(d.report().unknownCommands == 0);
  CHECK(d.report().malformed == 0);
  CHECK(d.report().commands == 9);
  for (PaletteIndex p : d.image().pixels) CHECK(p == 0);  // nothing drawn
  CHECK(decode("!XYZ 1\r").report().unknownCommands == 1);  // an unknown name is still counted
}
