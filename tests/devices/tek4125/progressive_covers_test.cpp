// The progressive stream's covers (tek4125_covers.hpp) and its row order
// (rowsByGain, tek4125_progressive.hpp), on small synthetic pictures: a
// cover takes its band's average colour, not one row's; finer levels paint
// only where the screen still differs; what the covers record as shown is
// what the emulator draws from their bytes; draft rows come nearer the
// picture than the covers for fewer bytes than the exact rows; rows go by
// the error they remove a byte, each once.
#include <catch2/catch.hpp>

#include <set>

#include "devices/device_table.hpp"
#include "devices/tek4125/tek4125_covers.hpp"
#include "devices/tek4125/tek4125_forms.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "devices/tek4125/tek4125_progressive.hpp"
#include "devices/tek4125/tek4125_run_cost.hpp"
#include "foundation/byte_sink.hpp"
#include "quantize/rate_distortion_runs.hpp"

using namespace lattice;

namespace {

constexpr int kWidth = 32, kHeight = 16;
const Palette kPalette = {Rgb8{0, 0, 0},       Rgb8{150, 150, 150}, Rgb8{20, 10, 0},     Rgb8{250, 200, 100},
                          Rgb8{100, 100, 100}, Rgb8{200, 200, 200}, Rgb8{155, 150, 150}, Rgb8{105, 100, 100}};

struct Covered {
  std::vector<int> shown;
  std::uint64_t rectangles = 0;
  std::vector<PaletteIndex> screen;  // what the emulator draws from the covers' bytes
};

// The covers of `pixels` alone, planned and then sent after a Tek-mode
// select, on a screen the picture's size.
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
  const auto covers = tek4125::planCovers(kWidth, kHeight, forms.fullXy, pixels, kPalette, 0, c.shown);
  c.rectangles = covers.size();
  std::vector<int> sent(pixels.size(), -1);
  tek4125::sendCovers(out, layout, covers, sent);
  CHECK(sent == c.shown);  // sending paints what planning recorded
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
  SECTION("one colour: one rectangle a band of the first level, nothing finer") {
    const Covered c = cover(picture([](int, int) { return PaletteIndex(1); }));
    CHECK(c.rectangles == std::uint64_t((kHeight + tek4125::kCoverLevels[0] - 1) / tek4125::kCoverLevels[0]));
    CHECK(std::count(c.shown.begin(), c.shown.end(), 1) == kWidth * kHeight);
  }
  SECTION("bands whose halves differ: the next level paints each half") {
    static_assert(tek4125::kCoverLevels[0] == 2 * tek4125::kCoverLevels[1] && tek4125::kCoverLevels[0] <= kHeight);
    const auto pixels = picture([](int, int y) {
      return PaletteIndex(y % tek4125::kCoverLevels[0] < tek4125::kCoverLevels[1] ? 2 : 3);
    });
    const Covered c = cover(pixels);
    for (std::size_t i = 0; i < pixels.size(); ++i) CHECK(c.shown[i] == pixels[i]);
  }
}

TEST_CASE("covers: what they record as shown is what the emulator draws from their bytes") {
  const auto pixels = picture([](int x, int y) { return PaletteIndex((x / 5 + y / 3 + x * y % 7 / 6) % 8); });
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

TEST_CASE("progressive: draft rows come nearer the picture than the covers, for fewer bytes than exact rows") {
  // Stripes three pixels wide, too narrow for a rectangle to pay but worth
  // their run codes, with specks of a colour near the stripe's, worth
  // neither: the covers blur the stripes, a draft keeps them and drops the specks.
  const auto pixels = picture([](int x, int y) {
    const bool speck = (x * 7 + y * 13) % 5 == 0;
    return PaletteIndex(x / 3 % 2 ? (speck ? 7 : 4) : (speck ? 6 : 1));
  });
  auto error = [&](const std::vector<int>& shown) {
    double e = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i)
      e += quantize::colourError(kPalette[pixels[i]], tek4125::colourShown(kPalette, shown[i], 0));
    return e;
  };
  const Covered covered = cover(pixels);
  tek4125::Tek4125Profile profile;
  // Costs and layout as for a picture of more than 16 colours: RL at 8 bits, strict's one way then.
  const quantize::RunCost cost = tek4125::tek4125RunCost(profile, 17, -1);
  tek4125::Tek4125RowLayout layout;
  layout.width = kWidth;
  layout.height = kHeight;
  layout.bits = 8;
  layout.raster = false;
  layout.runLength = true;
  const tek4125::ProgressivePlan plan =
      tek4125::planProgressive(kWidth, kHeight, -1, true, pixels, kPalette, 0, cost);
  // Rows drawn over the covers, as drafts and as they are: their bytes and what they leave shown.
  auto rows = [&](const std::vector<PaletteIndex>& drawn, std::vector<int>& shown) {
    CountingSink sink;
    tek4125::Tek4125Writer out(tek4125::tek4125Forms("strict"), sink);
    tek4125::Tek4125DriverOptions options;
    options.mergeRows = false;
    tek4125::Tek4125RowPlanner planner(out, layout, options);
    tek4125::drawRows(planner, pixels, drawn, kPalette, 0, shown);
    planner.finish();
    out.finish();
    return sink.bytesWritten();
  };
  std::vector<int> drafted = covered.shown, exact = covered.shown;
  const std::uint64_t draftBytes = rows(plan.drafts, drafted), exactBytes = rows(pixels, exact);
  INFO("draft " << draftBytes << " B, exact " << exactBytes << " B");
  CHECK(draftBytes < exactBytes);
  CHECK(error(drafted) < error(covered.shown));
  CHECK(error(drafted) > 0);  // a draft, not the picture
  CHECK(error(exact) == 0);
}

TEST_CASE("row planner: given what the screen shows, it skips the runs already there, whatever their colour") {
  tek4125::Tek4125RowLayout layout;
  layout.width = kWidth;
  layout.height = 1;
  layout.bits = 8;
  layout.raster = false;
  layout.runLength = true;
  layout.background = 0;
  std::vector<int> row(kWidth, 2);
  std::fill_n(row.begin(), 10, 1);
  std::fill_n(row.begin() + 10, 12, 3);
  std::vector<int> shown(kWidth, -1);
  std::copy_n(row.begin(), 22, shown.begin());  // the first two runs are on the screen already
  auto plan = [&](std::span<const int> what) {
    CountingSink sink;
    tek4125::Tek4125Writer out(tek4125::tek4125Forms("strict"), sink);
    tek4125::Tek4125RowPlanner planner(out, layout, tek4125::Tek4125DriverOptions{});
    planner.row(0, row, what);
    planner.finish();
    out.finish();
    return std::pair{sink.bytesWritten(), planner.stats().skippedPixels};
  };
  const auto [withShown, skipped] = plan(shown);
  const auto [without, none] = plan({});
  CHECK(skipped == 22);
  CHECK(none == 0);  // no run is the background colour
  CHECK(withShown < without);
}

TEST_CASE("progressive: the device's driver memory counts what the screen shows, the drafts and the covers") {
  const auto ordinary = devices::makeDevice("tek4125", {}).driverMemory(512, 512);
  const auto progressive = devices::makeDevice("tek4125", {"progressive=on"}).driverMemory(512, 512);
  // At least what the progressive driver holds a pixel beyond the frame: an int for what the
  // screen shows and a byte for the drafts.
  CHECK(progressive >= ordinary + std::uint64_t(512) * 512 * (sizeof(int) + 1));
}
