// The progressive stream's covers (tek4125_covers.hpp) and its row order
// (rowsByGain, tek4125_progressive.hpp), on small synthetic pictures: a
// cover takes its band's average colour, not one row's; finer levels paint
// only where the screen still differs; what the covers record as shown is
// what the emulator draws from their bytes; rows go by the error they
// remove a byte, each once.
#include <catch2/catch.hpp>

#include <set>

#include "devices/device_table.hpp"
#include "devices/tek4125/tek4125_covers.hpp"
#include "devices/tek4125/tek4125_forms.hpp"
#include "devices/tek4125/tek4125_progressive.hpp"
#include "foundation/byte_sink.hpp"

using namespace lattice;

namespace {

constexpr int kWidth = 32, kHeight = 16;
const Palette kPalette = {Rgb8{0, 0, 0},     Rgb8{150, 150, 150}, Rgb8{20, 10, 0},
                          Rgb8{250, 200, 100}, Rgb8{100, 100, 100}, Rgb8{200, 200, 200}};

struct Covered {
  std::vector<int> shown;
  std::uint64_t rectangles = 0;
  std::vector<PaletteIndex> screen;  // what the emulator draws from the covers' bytes
};

// The covers of `pixels` alone, after a Tek-mode select, on a screen the picture's size.
Covered cover(const std::vector<PaletteIndex>& pixels) {
  MemorySink sink;
  const tek4125::Tek4125Forms& forms = tek4125::tek4125Forms("strict");
  tek4125::Tek4125Writer out(forms, sink);
  out.bytes({0x1B, '%', '!', '0'});
  tek4125::Tek4125RowLayout layout;
  layout.width = kWidth;
  layout.height = kHeight;
  Covered c;
  c.shown.assign(pixels.size(), -1);
  c.rectangles = tek4125::drawCovers(out, layout, pixels, kPalette, 0, c.shown);
  out.finish();
  auto decoder = devices::makeDevice("tek4125", {"width=32", "height=16"}).makeEmulator();
  decoder->feed(sink.data());
  decoder->finish();
  CHECK(decoder->report().malformed == 0);
  c.screen = decoder->image().pixels;
  return c;
}

std::vector<PaletteIndex> picture(const std::function<PaletteIndex(int x, int y)>& f) {
  std::vector<PaletteIndex> p;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) p.push_back(f(x, y));
  return p;
}

}  // namespace

TEST_CASE("covers: a band's cover is its average colour, not one of its rows") {
  // Rows alternate dark and light grey; the mid grey between them is in the
  // palette and is what every band, at every level, averages to. A cover
  // copied from a row would paint one of the two greys, twice the error.
  const auto pixels = picture([](int, int y) { return PaletteIndex(y % 2 ? 5 : 4); });
  const Covered c = cover(pixels);
  CHECK(std::count(c.shown.begin(), c.shown.end(), 1) == kWidth * kHeight);
}

TEST_CASE("covers: finer levels paint only where the screen still differs") {
  SECTION("one colour: one rectangle a band, nothing finer") {
    const Covered c = cover(picture([](int, int) { return PaletteIndex(1); }));
    CHECK(c.rectangles == 2);
    CHECK(std::count(c.shown.begin(), c.shown.end(), 1) == kWidth * kHeight);
  }
  SECTION("bands whose halves differ: the 4-row level paints each half") {
    const auto pixels = picture([](int, int y) { return PaletteIndex(y % 8 < 4 ? 1 : 3); });
    const Covered c = cover(pixels);
    for (std::size_t i = 0; i < pixels.size(); ++i) CHECK(c.shown[i] == pixels[i]);
  }
}

TEST_CASE("covers: what they record as shown is what the emulator draws from their bytes") {
  const auto pixels = picture([](int x, int y) { return PaletteIndex((x / 5 + y / 3 + x * y % 7 / 6) % 6); });
  const Covered c = cover(pixels);
  CHECK(c.rectangles > 2);
  // Image row 0 is the screen's top row; the screen image is stored top row first too.
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const int expected = c.shown[i] < 0 ? 0 : c.shown[i];
    CHECK(int(c.screen[i]) == expected);
  }
}

TEST_CASE("progressive: rows go by the error they remove a byte, each once, ties in Adam7's order") {
  const auto pixels = picture([](int, int) { return PaletteIndex(1); });
  std::vector<int> shown(pixels.size(), 1);
  std::fill_n(shown.begin() + 5 * kWidth, kWidth, 2);        // row 5 wrong everywhere
  std::fill_n(shown.begin() + 9 * kWidth, kWidth / 4, 0);  // row 9 wrong on a quarter
  const std::vector<int> order = tek4125::rowsByGain(pixels, shown, kPalette, 0, kWidth, kHeight);
  REQUIRE(order.size() == std::size_t(kHeight));
  CHECK(std::set<int>(order.begin(), order.end()).size() == std::size_t(kHeight));
  CHECK(order[0] == 5);
  CHECK(order[1] == 9);
  std::vector<int> rest(order.begin() + 2, order.end()), adam7;
  for (int y : tek4125::progressiveRowOrder(kHeight))
    if (y != 5 && y != 9) adam7.push_back(y);
  CHECK(rest == adam7);
}
