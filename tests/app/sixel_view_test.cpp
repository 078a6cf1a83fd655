// lattice term's display: the screen scaled to the host's text area by
// nearest neighbour, drawn as sixel pictures one text row (a band) high,
// and redrawn only where it changed. The bytes are decoded by the project's
// sixel emulator, placed as a terminal places them (tests/support/sixel_screen.hpp).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "app/term/sixel_view.hpp"
#include "tests/support/sixel_screen.hpp"

namespace {

// A 1280 x 1024 screen of 256 colours in bands and columns, like a 4125's.
lattice::IndexedImage testScreen(int colours) {
  lattice::IndexedImage screen(1280, 1024, 256);
  for (int i = 0; i < 256; ++i)
    screen.colormap[static_cast<std::size_t>(i)] = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(255 - i),
                                                    static_cast<std::uint8_t>((i * 37) & 255)};
  for (int y = 0; y < screen.height; ++y)
    for (int x = 0; x < screen.width; ++x)
      screen.at(x, y) = static_cast<lattice::PaletteIndex>(((x / 40) * 7 + (y / 32) * 3) % colours);
  return screen;
}

// Every pixel of the host within `levels` of the view's colour.
bool showsWithin(const lattice::RgbImage& host, const lattice::IndexedImage& view, int levels) {
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const lattice::Rgb8 want = view.colorAt(x, y);
      const std::uint8_t* got = host.pixel(x, y);
      if (std::abs(got[0] - want.r) > levels || std::abs(got[1] - want.g) > levels || std::abs(got[2] - want.b) > levels)
        return false;
    }
  return true;
}

}  // namespace

TEST_CASE("term display: the screen scaled to fit, every pixel shown a pixel of the screen", "[term]") {
  const lattice::app::ViewGeometry host{100, 40, 10, 20, 256};
  const lattice::IndexedImage screen = testScreen(256);
  lattice::app::SixelView view(host, screen.width, screen.height);
  // 1000 x 740 pixels above the three text rows: the 5:4 screen fits by its height.
  CHECK(view.height() == 740);
  CHECK(view.width() == 925);
  CHECK(view.textRows() == 37);
  const std::string bytes = view.update(screen);
  const lattice::IndexedImage shown = view.shown();
  // Nearest neighbour: the view's pixel (x, y) is the screen's (x * 1280 / 925, y * 1024 / 740).
  for (int y = 0; y < shown.height; y += 7)
    for (int x = 0; x < shown.width; x += 5)
      REQUIRE(shown.at(x, y) == screen.at(x * 1280 / 925, y * 1024 / 740));
  const lattice::testing::SixelScreen host0 = lattice::testing::composeSixels(bytes, 1000, 800, 20);
  CHECK(host0.pictures == 1);  // the first draw: every band, one run
  // Sixel colours are whole percents: a gun moves by at most 1.3 levels.
  CHECK(showsWithin(host0.image, shown, 2));
}

TEST_CASE("term display: a redraw sends only the bands that changed", "[term]") {
  const lattice::app::ViewGeometry host{100, 40, 10, 20, 256};
  lattice::IndexedImage screen = testScreen(200);
  lattice::app::SixelView view(host, screen.width, screen.height);
  const std::string first = view.update(screen);
  CHECK(view.update(screen).empty());  // nothing changed, nothing sent
  // A mark near the screen's top left lands in the view's text row 3
  // (view y = 100 * 740 / 1024 = 72, band 72 / 20).
  for (int y = 100; y < 104; ++y)
    for (int x = 10; x < 50; ++x) screen.at(x, y) = 255;
  const std::string redraw = view.update(screen);
  const lattice::testing::SixelScreen drawn = lattice::testing::composeSixels(redraw, 1000, 800, 20);
  REQUIRE(drawn.pictures == 1);
  CHECK(drawn.rows == std::vector<int>{4});
  CHECK(redraw.size() * 10 < first.size());  // one band of 37, with the registers it uses
  CHECK(redraw.size() * 10 < view.fullFrame(screen).size());
  // The host's picture after both: the first draw, then the redraw over it.
  const lattice::testing::SixelScreen after = lattice::testing::composeSixels(first + redraw, 1000, 800, 20);
  CHECK(showsWithin(after.image, view.shown(), 2));
}

TEST_CASE("term display: more colours than the host's registers take the nearest kept colour", "[term]") {
  const lattice::app::ViewGeometry host{100, 40, 10, 20, 16};
  const lattice::IndexedImage screen = testScreen(12);  // fits 16 registers: exact
  lattice::app::SixelView view(host, screen.width, screen.height);
  const std::string bytes = view.update(screen);
  CHECK(showsWithin(lattice::testing::composeSixels(bytes, 1000, 800, 20).image, view.shown(), 2));
  const lattice::IndexedImage many = testScreen(64);  // does not: still drawn, with 16 colours a band run
  lattice::app::SixelView small(host, many.width, many.height);
  const std::string reduced = small.update(many);
  CHECK(lattice::testing::composeSixels(reduced, 1000, 800, 20).pictures == 1);
  CHECK(reduced.find("#16;") == std::string::npos);  // no register past 15 defined
}
