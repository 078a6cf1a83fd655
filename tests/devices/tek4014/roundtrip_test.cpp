// Driver to emulator: the screen the emulator shows is the driver's dithered
// dots, at the lower-left corner, in both address widths and every dither;
// each row goes out in its shorter form.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "devices/device_table.hpp"
#include "foundation/error.hpp"
#include "tests/devices/tek4014/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::tek4014;
using namespace lattice::tek4014::test;

namespace {

// Compares the emulator's screen with the dots: picture row r at screen row
// (frame height - 1 - r) counted from the bottom, every other pixel dark.
void checkScreen(const IndexedImage& screen, const std::vector<std::uint8_t>& dots, int w, int h) {
  long wrong = 0, lit = 0;
  for (int sy = 0; sy < screen.height; ++sy)
    for (int x = 0; x < screen.width; ++x) {
      const int fromBottom = screen.height - 1 - sy;
      const int r = h - 1 - fromBottom;
      const bool inFrame = x < w && r >= 0 && r < h;
      const std::uint8_t want =
          inFrame ? dots[static_cast<std::size_t>(r) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] : 0;
      lit += want;
      if (screen.at(x, sy) != want) ++wrong;
    }
  CHECK(lit > 0);
  CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("4014 round trip: every dither, both address widths") {
  const IndexedImage img = testing::ringsImage(96, 64);
  for (int bits : {10, 12})
    for (Tek4014Dither dither : {Tek4014Dither::FloydSteinberg, Tek4014Dither::Ordered, Tek4014Dither::Threshold}) {
      INFO(bits << "-bit, " << ditherName(dither));
      Tek4014Profile profile;
      profile.addressBits = bits;
      profile.dither = dither;
      Tek4014Stats stats;
      const auto stream = driveFrame(img, profile, &stats);
      CHECK(stats.bytes == stream.size());
      const Tek4014Decoder d = decode(stream, profile);
      CHECK(d.report().malformed == 0);
      CHECK(d.report().unknownCommands == 0);
      CHECK(d.image().width == profile.width());
      CHECK(d.image().height == profile.height());
      checkScreen(d.image(), ditheredDots(img, dither), img.width, img.height);
      // The stream opens with PAGE and leaves the terminal in alpha mode.
      REQUIRE(stream.size() > 4);
      CHECK(stream[0] == 0x1B);
      CHECK(stream[1] == 0x0C);
      CHECK(stream.back() == 0x1F);
    }
}

TEST_CASE("4014 round trip: the stream decodes the same fed a byte at a time") {
  const IndexedImage img = testing::gradientImage(40, 24);
  const Tek4014Profile profile;
  const auto stream = driveFrame(img, profile);
  Tek4014Decoder whole = decode(stream, profile);
  Tek4014Decoder bytewise(profile);
  for (std::uint8_t b : stream) bytewise.feed(std::span<const std::uint8_t>(&b, 1));
  bytewise.finish();
  CHECK(bytewise.image().pixels == whole.image().pixels);
  CHECK(bytewise.report().commands == whole.report().commands);
}

TEST_CASE("4014 driver: solid rows go as vectors, scattered dots as points, each the shorter") {
  const Tek4014Profile profile;
  // White rows: one run each, a vector (GS + 4 + 1 or so) beats 200 dots.
  {
    const IndexedImage white = testing::singleColourImage(200, 3, {255, 255, 255});
    Tek4014Stats s;
    const auto stream = driveFrame(white, profile, &s);
    CHECK(s.vectorRows == 3);
    CHECK(s.pointRows == 0);
    CHECK(s.dots == 600);
    CHECK(stream.size() < 40);
  }
  // 50% grey under the ordered dither: every other dot lit, runs of one:
  // a point costs one byte (Lo X), a one-dot vector at least three.
  {
    const IndexedImage grey = testing::singleColourImage(64, 8, {188, 188, 188});  // about 0.5 linear
    Tek4014Profile ordered = profile;
    ordered.dither = Tek4014Dither::Ordered;
    Tek4014Stats s;
    driveFrame(grey, ordered, &s);
    CHECK(s.pointRows == 8);
    CHECK(s.vectorRows == 0);
  }
  // Black: nothing but PAGE, the closing move and US.
  {
    const IndexedImage black = testing::singleColourImage(64, 8, {0, 0, 0});
    Tek4014Stats s;
    const auto stream = driveFrame(black, profile, &s);
    CHECK(s.dots == 0);
    CHECK(stream.size() == 2 + 1 + 4 + 1);
  }
}

TEST_CASE("4014 driver: a frame larger than the screen is refused with the way out") {
  MemorySink sink;
  Tek4014Driver driver(sink, Tek4014Profile{});
  const IndexedImage big = testing::singleColourImage(1025, 10, {1, 2, 3});
  CHECK_THROWS_WITH(driver.begin({big.width, big.height, big.colormap}),
                    Catch::Contains("1024x780") && Catch::Contains("bits=12"));
  Tek4014Profile twelve;
  twelve.addressBits = 12;
  Tek4014Driver wide(sink, twelve);
  CHECK_NOTHROW(wide.begin({big.width, big.height, big.colormap}));
}

TEST_CASE("4014 device: the table's entry, its profile keys and their errors") {
  const devices::Device d = devices::makeDevice("tek4014");
  CHECK(d.width == 1024);
  CHECK(d.height == 780);
  const devices::Device d12 = devices::makeDevice("tek4014", {"bits=12", "dither=ordered"});
  CHECK(d12.width == 4096);
  CHECK(d12.height == 3120);
  CHECK(d12.profileText.find("dither=ordered") != std::string::npos);
  CHECK_THROWS_WITH(devices::makeDevice("tek4014", {"bits=11"}), Catch::Contains("10") && Catch::Contains("12"));
  CHECK_THROWS_WITH(devices::makeDevice("tek4014", {"dither=random"}), Catch::Contains("floyd-steinberg"));
  CHECK_THROWS_AS(devices::makeDevice("tek4014", {"colours=2"}), Error);
}
