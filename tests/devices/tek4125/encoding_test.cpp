// Parameter encodings: the host-side encoder against the terminal-side
// readers the emulator uses, over the whole legal range.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "devices/tek4125/tek4125_encoding.hpp"
#include "devices/tek4125/tek4125_params.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4125;

namespace {

std::string text(const Bytes& b) { return std::string(b.begin(), b.end()); }

std::string intText(int v) {
  Bytes b;
  appendInt(b, v);
  return text(b);
}

// Feed bytes to a reader; the value must complete on exactly the last byte.
int readInt(const Bytes& b) {
  IntReader r;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const ReadStatus s = r.feed(b[i]);
    REQUIRE(s == (i + 1 == b.size() ? ReadStatus::Done : ReadStatus::More));
  }
  return r.value();
}

std::pair<int, int> readXy(const Bytes& b, std::size_t& pos, XyRegisters& regs) {
  XyReader r;
  while (pos < b.size()) {
    const ReadStatus s = r.feed(b[pos++], regs);
    REQUIRE(s != ReadStatus::Bad);
    if (s == ReadStatus::Done) return {regs.x(), regs.y()};
  }
  FAIL("xy did not end with a Lo-X byte");
  return {-1, -1};
}

}  // namespace

TEST_CASE("integers encode as the 4100 manual's examples") {
  CHECK(intText(0) == "0");
  CHECK(intText(1) == "1");
  CHECK(intText(-1) == "!");
  CHECK(intText(11) == ";");
  CHECK(intText(34) == "B2");
  CHECK(intText(15) == "?");  // gnuplot's ML? line index 15
  CHECK(intText(1024) == "A@0");
  CHECK(intText(65535).size() == 3);
  CHECK(intLength(15) == 1);
  CHECK(intLength(-16) == 2);
  CHECK(intLength(1023) == 2);
  CHECK(intLength(-1024) == 3);
  for (int v : {0, 1, -1, 11, 34, 15, 1024, 65535, -65535}) {
    Bytes b;
    appendInt(b, v);
    CHECK(readInt(b) == v);
  }
}

TEST_CASE("every integer in -65535..65535 round-trips through the decoder's reader") {
  long failures = 0;
  for (int v = -kMaxIntMagnitude; v <= kMaxIntMagnitude; ++v) {
    Bytes b;
    appendInt(b, v);
    if (static_cast<int>(b.size()) != intLength(v)) ++failures;
    IntReader r;
    ReadStatus s = ReadStatus::More;
    for (std::size_t i = 0; i < b.size() && s == ReadStatus::More; ++i) s = r.feed(b[i]);
    // -0 does not exist on the wire; 0 must come back as 0.
    if (s != ReadStatus::Done || r.value() != v) ++failures;
  }
  CHECK(failures == 0);
}

TEST_CASE("integers outside the 16-bit magnitude are a driver bug, not silently wrapped") {
  Bytes b;
  CHECK_THROWS_AS(appendInt(b, 65536), Error);
  CHECK_THROWS_AS(appendInt(b, -65536), Error);
  CHECK(b.empty());
}

TEST_CASE("an integer reader rejects a third Hi-I character and non-parameter bytes") {
  IntReader r;
  CHECK(r.feed('A') == ReadStatus::More);
  CHECK(r.feed('A') == ReadStatus::More);
  CHECK(r.feed('A') == ReadStatus::Bad);
  IntReader r2;
  CHECK(r2.feed(0x1F) == ReadStatus::Bad);
}

TEST_CASE("integer arrays, reals and strings carry their counts") {
  Bytes b;
  const int values[] = {1, -2, 300};
  appendIntArray(b, values);
  CHECK(text(b) == "3" "1" "\"" "R<");  // 300 = 18*16 + 12: Hi-I 'R', Lo-I '<'
  b.clear();
  appendString(b, "AB");
  CHECK(text(b) == "2AB");
  b.clear();
  appendReal(b, 90.0);  // whole numbers go with exponent 0, as gnuplot's MR "E:0"
  CHECK(text(b) == "E:0");
  b.clear();
  appendReal(b, 0.75);  // 3 * 2^-2
  CHECK(text(b) == "3\"");
  for (double v : {0.0, 1.0, -3.25, 0.1, 1234.5678, -1e-3, 65535.0, 1e6}) {
    Bytes r;
    appendReal(r, v);
    IntReader ir;
    std::size_t i = 0;
    while (ir.feed(r[i++]) == ReadStatus::More) {}
    const int mantissa = ir.value();
    ir.reset();
    while (i < r.size() && ir.feed(r[i++]) == ReadStatus::More) {}
    REQUIRE(i == r.size());
    const double back = std::ldexp(mantissa, ir.value());
    CHECK(back == Approx(v).epsilon(2e-5).margin(1e-12));
  }
}

TEST_CASE("xy full form is five bytes in Hi-Y, Extra, Lo-Y, Hi-X, Lo-X order") {
  const XyBytes b = xyBytes(4095, 4095);
  CHECK(b == XyBytes{0x3F, 0x6F, 0x7F, 0x3F, 0x5F});  // DEL (0x7F) is a legal Lo-Y
  XyEncoder e;
  Bytes out;
  e.append(out, 1, 2);
  CHECK(out.size() == 5);
  CHECK_THROWS_AS(xyBytes(4096, 0), Error);
  CHECK_THROWS_AS(xyBytes(0, -1), Error);
}

TEST_CASE("every x for a set of y and every y for a set of x round-trip, in full form") {
  long failures = 0;
  auto check = [&](int x, int y) {
    XyEncoder e;
    Bytes b;
    e.append(b, x, y);
    XyRegisters regs;
    std::size_t pos = 0;
    XyReader r;
    ReadStatus s = ReadStatus::More;
    while (pos < b.size() && s == ReadStatus::More) s = r.feed(b[pos++], regs);
    if (s != ReadStatus::Done || pos != b.size() || regs.x() != x || regs.y() != y) ++failures;
  };
  for (int fixed : {0, 1, 2, 3, 4, 127, 128, 1023, 2048, 3071, 4094, 4095})
    for (int v = 0; v <= kMaxCoordinate; ++v) {
      check(v, fixed);
      check(fixed, v);
    }
  std::mt19937 rng(4125);
  for (int i = 0; i < 100000; ++i) check(static_cast<int>(rng() % 4096), static_cast<int>(rng() % 4096));
  CHECK(failures == 0);
}

TEST_CASE("short-form xy sequences decode with the registers the terminal keeps") {
  std::mt19937 rng(1988);
  XyEncoder e;
  Bytes b;
  std::vector<std::pair<int, int>> sent;
  int x = 2000, y = 2000;
  for (int i = 0; i < 50000; ++i) {
    switch (rng() % 4) {  // mix of walks (most bytes unchanged) and jumps
      case 0: x = static_cast<int>(rng() % 4096), y = static_cast<int>(rng() % 4096); break;
      case 1: x = std::clamp(x + static_cast<int>(rng() % 9) - 4, 0, 4095); break;
      case 2: y = std::clamp(y + static_cast<int>(rng() % 9) - 4, 0, 4095); break;
      default: break;  // repeat: only Lo-X goes out
    }
    const int predicted = e.length(x, y);
    const std::size_t before = b.size();
    e.append(b, x, y);
    REQUIRE(static_cast<int>(b.size() - before) == predicted);
    sent.emplace_back(x, y);
  }
  CHECK(b.size() < sent.size() * 5);  // the short forms did shorten the stream
  XyRegisters regs;
  std::size_t pos = 0;
  long failures = 0;
  for (const auto& p : sent)
    if (readXy(b, pos, regs) != p) ++failures;
  CHECK(failures == 0);
  CHECK(pos == b.size());
}

TEST_CASE("the short forms leave out exactly the unchanged leading bytes") {
  XyEncoder e;
  Bytes b;
  e.append(b, 100, 100);
  b.clear();
  e.append(b, 100, 100);  // nothing changed: Lo-X alone
  CHECK(b.size() == 1);
  b.clear();
  e.append(b, 101, 100);  // Extra changed: Extra, Lo-Y, Lo-X
  CHECK(b.size() == 3);
  b.clear();
  e.append(b, 105, 100);  // Lo-X only... x&3 same as 101, (105>>2)&31 differs
  CHECK(b.size() == 1);
  b.clear();
  e.append(b, 105 + 128, 100);  // Hi-X changed: Lo-Y must precede it
  CHECK(b.size() == 3);
  CHECK(b[0] == xyBytes(233, 100).loY);
}
