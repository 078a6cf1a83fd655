// Tek 4010/4014 addresses: the encoder's compression rules and the
// assembler's reading of them (docs/tek4014-sources.md).
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "devices/tek4014/tek4014_address.hpp"

using namespace lattice::tek4014;

namespace {

// Feeds bytes to an assembler; the number of addresses completed.
int feed(AddressAssembler& a, const std::string& bytes) {
  int done = 0;
  for (char c : bytes) done += a.add(static_cast<std::uint8_t>(c)) ? 1 : 0;
  return done;
}

}  // namespace

TEST_CASE("4014 address: the byte tags and a worked 10-bit example") {
  // x = 400 (Hi X 01100, Lo X 10000), y = 300 (Hi Y 01001, Lo Y 01100) in
  // 10-bit units: Hi Y ')', Lo Y 'l', Hi X ',', Lo X 'P'.
  AddressEncoder e(false);
  std::string out;
  e.encode(400 << 2, 300 << 2, out);
  CHECK(out == ")l,P");
  AddressAssembler a;
  CHECK(feed(a, out) == 1);
  CHECK(a.x() == 1600);
  CHECK(a.y() == 1200);
  // The same with an extra byte of zeros (12-bit form): same point.
  AddressEncoder e12(true);
  std::string out12;
  e12.encode(1600, 1200, out12);
  CHECK(out12 == ")`l,P");
  AddressAssembler b;
  CHECK(feed(b, out12) == 1);
  CHECK(b.x() == 1600);
  CHECK(b.y() == 1200);
}

TEST_CASE("4014 address: only the bytes that changed are sent") {
  AddressEncoder e(false);
  std::string out;
  e.encode(0, 100 << 2, out);
  CHECK(out.size() == 4);  // the first address: everything
  out.clear();
  e.encode(5 << 2, 100 << 2, out);  // same row, same Hi X
  CHECK(out == std::string(1, char(0x40 | 5)));
  out.clear();
  e.encode(40 << 2, 100 << 2, out);  // Hi X changed: Lo Y must come first so Hi X reads as Hi X
  CHECK(out.size() == 3);
  CHECK((out[0] & 0x60) == 0x60);
  CHECK((out[1] & 0x60) == 0x20);
  out.clear();
  e.encode(40 << 2, 101 << 2, out);  // Lo Y only
  CHECK(out.size() == 2);
  out.clear();
  e.encode(40 << 2, 200 << 2, out);  // Hi Y and Lo Y
  CHECK(out.size() == 3);
  CHECK(e.cost(40 << 2, 200 << 2) == 1);

  AddressEncoder e12(true);
  out.clear();
  e12.encode(100, 100, out);
  out.clear();
  e12.encode(101, 100, out);  // the low bits changed: extra byte, Lo Y, Lo X
  CHECK(out.size() == 3);
}

TEST_CASE("4014 address: any sequence of compressed addresses decodes to the points encoded") {
  for (bool twelve : {false, true}) {
    INFO((twelve ? "12-bit" : "10-bit"));
    std::mt19937 rng(twelve ? 12 : 10);
    AddressEncoder e(twelve);
    AddressAssembler a;
    for (int i = 0; i < 20000; ++i) {
      // Mostly near the last point (the compressed cases), sometimes anywhere.
      const int x = static_cast<int>(rng() % 4096) & (twelve ? 4095 : 4092);
      const int y = static_cast<int>(rng() % 4096) & (twelve ? 4095 : 4092);
      std::string out;
      e.encode(x, y, out);
      REQUIRE(static_cast<int>(out.size()) <= (twelve ? 5 : 4));
      REQUIRE(feed(a, out) == 1);
      REQUIRE(a.x() == x);
      REQUIRE(a.y() == y);
      const int nx = std::min(twelve ? 4095 : 4092, x + static_cast<int>(rng() % 8) * (twelve ? 1 : 4));
      out.clear();
      e.encode(nx, y, out);
      REQUIRE(feed(a, out) == 1);
      REQUIRE(a.x() == nx);
      REQUIRE(a.y() == y);
    }
  }
}

TEST_CASE("4014 address: a control byte's abandonment leaves the last point, high bytes read as Lo Y") {
  AddressAssembler a;
  CHECK(feed(a, ")l,P") == 1);
  CHECK(feed(a, "*m") == 0);  // Hi Y, Lo Y, then abandoned
  a.start();
  CHECK(feed(a, "Q") == 1);  // Lo X alone: the old Y, the new Lo X
  CHECK(a.y() == 1200);
  CHECK(a.x() == (1600 & ~(31 << 2)) + (17 << 2));
  // 0xEC inside an address is Lo Y 12, as 'l' is.
  AddressAssembler b;
  CHECK(feed(b, std::string{')', char(0xEC), ',', 'P'}) == 1);
  CHECK(b.y() == 1200);
}
