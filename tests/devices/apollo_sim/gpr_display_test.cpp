#include <catch2/catch.hpp>

#include <vector>

#include "devices/apollo_sim/apollo_profile.hpp"
#include "devices/apollo_sim/gpr_display.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::apollo;

TEST_CASE("profiles have the GPR sizes of the DN660 and DN580") {
  ApolloProfile dn660 = dn660Profile(8);
  CHECK(dn660.width == 1024);
  CHECK(dn660.height == 1024);
  CHECK(dn660.colorMapEntries() == 256);
  CHECK(dn660Profile(4).colorMapEntries() == 16);
  ApolloProfile dn580 = apolloProfileByName("dn580");
  CHECK(dn580.width == 1280);
  CHECK(dn580.height == 1024);
  CHECK(dn580.planes == 8);
  CHECK(apolloProfileByName("dn660-4").planes == 4);
  CHECK_THROWS_AS(dn660Profile(6), Error);
  CHECK_THROWS_AS(apolloProfileByName("dn3000"), Error);
}

TEST_CASE("display characteristics report the profile") {
  GprDisplay display;
  display.init(GprDisplayMode::Borrow, dn660Profile(4));
  GprDisplayCharacteristics c = display.inqDispCharacteristics();
  CHECK(c.xVisibleSize == 1024);
  CHECK(c.yVisibleSize == 1024);
  CHECK(c.nPlanes == 4);
  CHECK(c.lutWidthPerPrimary == 8);
  CHECK(c.colorMapEntries == 16);
}

TEST_CASE("write_pixels stores a row through the planes and the colour map shows it") {
  GprDisplay display;
  display.init(GprDisplayMode::Borrow, dn660Profile(4));
  display.acquireDisplay();
  std::vector<std::uint32_t> map{0x000000, 0xFF8000, 0x0000FF};
  display.setColorMap(0, map);
  display.clear(2);
  std::vector<std::uint32_t> row{1, 0, 17};  // 17 keeps its low 4 bits: 1
  display.writePixels(row, GprWindow{10, 20, 3, 1});
  display.releaseDisplay();
  CHECK(display.pixel(10, 20) == 1);
  CHECK(display.pixel(11, 20) == 0);
  CHECK(display.pixel(12, 20) == 1);
  CHECK(display.pixel(13, 20) == 2);  // cleared
  IndexedImage screen = display.snapshot();
  CHECK(screen.colormap.size() == 16);
  CHECK(screen.colorAt(10, 20) == Rgb8{255, 128, 0});
  CHECK(screen.colorAt(0, 0) == Rgb8{0, 0, 255});
}

TEST_CASE("GPR calls out of order or out of range are refused") {
  GprDisplay display;
  std::vector<std::uint32_t> one{0};
  CHECK_THROWS_AS(display.acquireDisplay(), Error);  // before init
  display.init(GprDisplayMode::Borrow, dn660Profile(8));
  CHECK_THROWS_AS(display.writePixels(one, GprWindow{0, 0, 1, 1}), Error);  // not acquired
  display.acquireDisplay();
  CHECK_THROWS_AS(display.acquireDisplay(), Error);
  CHECK_THROWS_AS(display.writePixels(one, GprWindow{1024, 0, 1, 1}), Error);
  CHECK_THROWS_AS(display.writePixels(one, GprWindow{0, 0, 2, 1}), Error);  // too few values
  std::vector<std::uint32_t> bad{0x1000000};
  CHECK_THROWS_AS(display.setColorMap(0, bad), Error);
  CHECK_THROWS_AS(display.setColorMap(256, one), Error);
  display.releaseDisplay();
  display.terminate();
  CHECK_THROWS_AS(display.inqDispCharacteristics(), Error);

  GprDisplay frameMode;  // frame mode owns the screen: no acquire needed
  frameMode.init(GprDisplayMode::Frame, dn580Profile());
  frameMode.writePixels(one, GprWindow{1279, 1023, 1, 1});
  CHECK(frameMode.pixel(1279, 1023) == 0);
}
