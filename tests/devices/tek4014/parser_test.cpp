// The 4014 emulator on streams our driver never writes: the other modes
// xterm's Tek window accepts, cut-off and garbled input, and its work budget.
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "devices/tek4014/tek4014_decoder.hpp"
#include "devices/work_budget.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4014;

namespace {

std::vector<std::uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }

Tek4014Decoder run(const std::string& s, Tek4014Profile profile = {}) {
  Tek4014Decoder d(profile);
  d.feed(bytes(s));
  d.finish();
  return d;
}

// Lit pixel at (x, y) in 10-bit units, y counted from the bottom.
bool lit(const Tek4014Decoder& d, int x, int y) { return d.image().at(x, d.image().height - 1 - y) == 1; }

long litCount(const Tek4014Decoder& d) {
  long n = 0;
  for (auto p : d.image().pixels) n += p;
  return n;
}

// A full 10-bit address (Hi Y, Lo Y, Hi X, Lo X).
std::string at(int x, int y) {
  return {char(0x20 | (y >> 5)), char(0x60 | (y & 31)), char(0x20 | (x >> 5)), char(0x40 | (x & 31))};
}

}  // namespace

TEST_CASE("4014 emulator: graph mode moves first, then draws, GS BEL draws the first vector") {
  const Tek4014Decoder d = run(std::string("\x1d") + at(10, 10) + at(20, 10) + "\x1f");
  CHECK(litCount(d) == 11);
  CHECK(lit(d, 10, 10));
  CHECK(lit(d, 20, 10));
  // GS BEL: from the beam (left at 20,10 by the previous vector) to 20,30.
  const Tek4014Decoder e = run(std::string("\x1d") + at(10, 10) + at(20, 10) + std::string("\x1d\x07") + at(20, 30));
  CHECK(litCount(e) == 11 + 20);
}

TEST_CASE("4014 emulator: point plot, special point plot and incremental plot") {
  const Tek4014Decoder p = run(std::string("\x1c") + at(5, 6) + at(7, 6));
  CHECK(litCount(p) == 2);
  CHECK(lit(p, 5, 6));
  CHECK(lit(p, 7, 6));
  // ESC FS: an intensity byte before each address.
  const Tek4014Decoder s = run(std::string("\x1b\x1c" "~") + at(9, 9) + std::string("~") + at(11, 9));
  CHECK(litCount(s) == 2);
  CHECK(lit(s, 11, 9));
  // RS from a point plotted at (100, 100): pen down, 8 steps north-east in
  // 12-bit units is 2 pixels of the 10-bit screen.
  const Tek4014Decoder r = run(std::string("\x1c") + at(100, 100) + std::string("\x1eP") + std::string(8, 'E'));
  CHECK(lit(r, 102, 102));
  CHECK(r.beamX() == 408);
  CHECK(r.beamY() == 408);
}

TEST_CASE("4014 emulator: ESC FF erases, line styles and other escapes are known") {
  const Tek4014Decoder d = run(std::string("\x1c") + at(5, 6) + "\x1b\x0c");
  CHECK(litCount(d) == 0);
  // After ESC, LF, CR and the high half are ignored and the escape goes on.
  const Tek4014Decoder h = run(std::string("\x1c") + at(5, 6) + "\x1b\x85\r\x0c");
  CHECK(litCount(h) == 0);
  CHECK(h.report().unknownCommands == 0);
  const Tek4014Decoder e = run("\x1b\x61\x1b\x38\x1b\x05\x1b\x17\x1b\x0e\x1b\x0f");
  CHECK(e.lineStyle() == 1);
  CHECK(e.report().unknownCommands == 0);
  CHECK(e.report().malformed == 0);
  // A dashed vector is drawn solid, and the report says so.
  const Tek4014Decoder f = run(std::string("\x1b\x61\x1d") + at(0, 0) + at(9, 0));
  CHECK(litCount(f) == 10);
  CHECK(f.report().unknownByName.count("dashed line style (drawn solid)") == 1);
  // An unknown escape is named; an OSC is skipped to its BEL.
  const Tek4014Decoder g = run(std::string("\x1b!\x1b]0;title\x07\x1c") + at(1, 1));
  CHECK(g.report().unknownByName.count("ESC 0x21") == 1);
  CHECK(litCount(g) == 1);
}

TEST_CASE("4014 emulator: cut-off and garbled addresses, text, high bytes") {
  // A control byte inside an address abandons it.
  const Tek4014Decoder a = run(std::string("\x1c") + at(5, 6).substr(0, 2) + std::string("\x1c") + at(7, 6));
  CHECK(a.report().malformed == 1);
  CHECK(litCount(a) == 1);
  // The end of the stream inside an address.
  const Tek4014Decoder b = run(std::string("\x1c") + at(5, 6).substr(0, 3));
  CHECK(b.report().malformed == 1);
  CHECK(litCount(b) == 0);
  // Alpha text is not drawn, and counted once per run.
  const Tek4014Decoder c = run("\x1fhello world\r\n");
  CHECK(c.report().unknownCommands == 2);
  CHECK(litCount(c) == 0);
  // 0x80..0xFF where an address could start are ignored.
  const Tek4014Decoder h = run(std::string("\x1c\x80\xff") + at(3, 3));
  CHECK(litCount(h) == 1);
  CHECK(lit(h, 3, 3));
}

TEST_CASE("4014 emulator: random bytes never throw, and chunking never matters") {
  std::mt19937 rng(4014);
  for (int round = 0; round < 20; ++round) {
    std::vector<std::uint8_t> junk(20000);
    for (auto& b : junk) b = static_cast<std::uint8_t>(rng() % (round % 2 ? 256 : 0x80));
    Tek4014Decoder whole;
    REQUIRE_NOTHROW(whole.feed(junk));
    whole.finish();
    Tek4014Decoder pieces;
    for (std::size_t i = 0; i < junk.size(); i += 7)
      pieces.feed(std::span<const std::uint8_t>(junk).subspan(i, std::min<std::size_t>(7, junk.size() - i)));
    pieces.finish();
    CHECK(pieces.image().pixels == whole.image().pixels);
    CHECK(pieces.report().commands == whole.report().commands);
  }
}

TEST_CASE("4014 emulator: erases and vectors are charged, a stream of erases is refused past the budget") {
  {
    Tek4014Decoder d;
    decodeBytes(d, bytes(std::string("\x1d") + at(0, 0) + at(1023, 0) + at(1023, 779)), "v.tek");
    CHECK(d.report().pixelWork == 1024 + 780);
  }
  Tek4014Profile twelve;
  twelve.addressBits = 12;
  const std::uint64_t screen = 4096ull * 3120ull;
  const std::uint64_t fit = kPixelWorkBudget / screen;
  std::string pages;
  for (std::uint64_t i = 0; i < fit; ++i) pages += "\x1b\x0c";
  {
    Tek4014Decoder d(twelve);
    REQUIRE_NOTHROW(decodeBytes(d, bytes(pages), "fits.tek"));
  }
  Tek4014Decoder d(twelve);
  CHECK_THROWS_WITH(decodeBytes(d, bytes(pages + "\x1b\x0c"), "erase.tek"),
                    Catch::Contains("erase.tek") && Catch::Contains("kPixelWorkBudget"));
}
