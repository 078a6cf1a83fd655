// Driver -> bytes -> emulator: the picture must come back pixel for pixel,
// the colours within the 0..100 percent quantization, whatever the chunking.
#include <catch2/catch.hpp>

#include <random>

#include "devices/gun_percent.hpp"
#include "tests/devices/tek4125/tek_test_support.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

IndexedImage decode(const std::vector<std::uint8_t>& bytes, const Tek4125Profile& profile,
                    int w, int h, DecodeReport* report = nullptr) {
  Tek4125Decoder decoder(profile);
  decoder.feed(bytes);
  decoder.finish();
  if (report) *report = decoder.report();
  return cutPicture(decoder.image(), profile, w, h);
}

// Same picture: every pixel's colour-map index, offset by the reserved entries.
void checkSamePicture(const IndexedImage& sent, const IndexedImage& got, const Tek4125Profile& profile) {
  long differing = 0;
  for (int y = 0; y < sent.height; ++y)
    for (int x = 0; x < sent.width; ++x)
      if (got.at(x, y) != sent.at(x, y) + profile.reserved) ++differing;
  CHECK(differing == 0);
  int worst = 0;
  for (std::size_t i = 0; i < sent.colormap.size(); ++i) {
    const Rgb8 a = sent.colormap[i], b = got.colormap.at(i + static_cast<std::size_t>(profile.reserved));
    worst = std::max({worst, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
  }
  // One percent step is 2.55 of 8 bits; rounding both ways keeps within 2.
  CHECK(worst <= 2);
}

}  // namespace

TEST_CASE("synthetic pictures survive driver -> emulator at 4 and 8 planes, every strategy and form set") {
  for (const std::string forms : {"strict", "compact"})
    for (int planes : {4, 8}) {
      Tek4125Profile profile;
      profile.forms = forms;
      profile.planes = planes;
      const int colors = profile.maxColors();
      struct Case {
        const char* name;
        IndexedImage image;
      };
      const Case cases[] = {
          {"gradient", gradient(97, 61, colors)},
          {"noise", noise(100, 40, colors, 11u)},
          {"single colour", flat(64, 32, colors, static_cast<PaletteIndex>(colors - 1))},
          {"all background", flat(33, 17, colors, 0)},
          {"1x1", flat(1, 1, colors, 5)},
          {"width 1 column", noise(1, 50, colors, 3u)},
          {"width not divisible by 3", noise(301, 7, colors, 5u)},
          {"scene", scene(160, 120, colors)},
          {"full screen", noise(1280, 4, colors, 9u)},
          {"long runs", gradient(1200, 3, 3)},
      };
      for (const Case& c : cases) {
        INFO(c.name << " at " << planes << " planes, " << forms);
        for (const Tek4125NamedStrategy& strategy : tek4125Strategies()) {
          INFO("strategy " << strategy.name);
          DecodeReport report;
          const IndexedImage got = decode(encode(c.image, profile, strategy.options), profile, c.image.width,
                                          c.image.height, &report);
          checkSamePicture(c.image, got, profile);
          CHECK(report.malformed == 0);
          CHECK(report.unknownCommands == 0);
        }
      }
    }
}

TEST_CASE("a full 1280x1024 picture fills the screen exactly") {
  Tek4125Profile profile;
  const IndexedImage img = gradient(1280, 1024, 256);
  Tek4125Decoder decoder(profile);
  decoder.feed(encode(img, profile));
  decoder.finish();
  CHECK(decoder.image().pixels == img.pixels);
}

TEST_CASE("reserved colour-map entries are left alone and the picture is shifted past them") {
  for (const std::string forms : {"strict", "compact"}) {
    INFO(forms);
    Tek4125Profile profile;
    profile.forms = forms;
    profile.planes = 4;
    profile.reserved = 2;
    const IndexedImage img = scene(90, 50, profile.maxColors());
    Tek4125Decoder decoder(profile);
    decoder.feed(encode(img, profile));
    checkSamePicture(img, cutPicture(decoder.image(), profile, img.width, img.height), profile);
    const Palette defaults = Tek4125Decoder::defaultColorMap(16);
    CHECK(decoder.image().colormap[0] == defaults[0]);
    CHECK(decoder.image().colormap[1] == defaults[1]);
  }
}

TEST_CASE("the picture is centred and the rest of the screen is cleared to index 0") {
  for (const std::string forms : {"strict", "compact"}) {
    INFO(forms);
    Tek4125Profile profile;
    profile.forms = forms;
    const IndexedImage img = flat(100, 50, 4, 3);
    Tek4125Decoder decoder(profile);
    decoder.feed(encode(img, profile));
    const IndexedImage& screen = decoder.image();
    long lit = 0;
    for (PaletteIndex p : screen.pixels) lit += p == 3;
    CHECK(lit == 100 * 50);
    CHECK(screen.at(590, 487) == 3);  // (1280-100)/2 = 590; top row (1024-50)/2 = 487
    CHECK(screen.at(689, 536) == 3);
    CHECK(screen.at(589, 487) == 0);
    CHECK(screen.at(690, 536) == 0);
    CHECK(screen.at(590, 486) == 0);
    CHECK(screen.at(590, 537) == 0);
  }
}

TEST_CASE("the decoded picture does not depend on how the stream is chunked") {
  Tek4125Profile profile;
  profile.planes = 4;
  const IndexedImage img = scene(120, 80, 16);
  const std::vector<std::uint8_t> bytes = encode(img, profile);
  Tek4125Decoder whole(profile);
  whole.feed(bytes);
  whole.finish();
  Tek4125Decoder single(profile);
  for (std::uint8_t b : bytes) single.feed(std::span<const std::uint8_t>(&b, 1));
  single.finish();
  CHECK(single.image().pixels == whole.image().pixels);
  CHECK(single.image().colormap == whole.image().colormap);
  CHECK(single.report().commands == whole.report().commands);
  std::mt19937 rng(42);
  for (int trial = 0; trial < 5; ++trial) {
    Tek4125Decoder chunked(profile);
    for (std::size_t pos = 0; pos < bytes.size();) {
      const std::size_t n = std::min<std::size_t>(bytes.size() - pos, 1 + rng() % 200);
      chunked.feed(std::span<const std::uint8_t>(bytes).subspan(pos, n));
      pos += n;
    }
    chunked.finish();
    CHECK(chunked.image().pixels == whole.image().pixels);
    CHECK(chunked.report().bytes == bytes.size());
  }
}

TEST_CASE("palette quantization to percent rounds to nearest and back") {
  CHECK(devices::percentOf8(0) == 0);
  CHECK(devices::percentOf8(255) == 100);
  CHECK(devices::percentOf8(128) == 50);
  CHECK(devices::percentOf8(1) == 0);
  CHECK(devices::percentOf8(2) == 1);
  for (int v = 0; v < 256; ++v)
    CHECK(std::abs(devices::eightOfPercent(devices::percentOf8(static_cast<std::uint8_t>(v))) - v) <=
          devices::kPercentRoundTripMaxDelta);
}

TEST_CASE("the driver refuses pictures and palettes the terminal cannot show") {
  Tek4125Profile profile;
  profile.planes = 4;
  MemorySink sink;
  Tek4125Driver driver(sink, profile);
  CHECK(driver.maxColors() == 16);
  CHECK_THROWS_AS(driver.begin(FrameInfo{1281, 10, spreadPalette(4)}), Error);
  CHECK_THROWS_AS(driver.begin(FrameInfo{10, 10, spreadPalette(17)}), Error);
  CHECK_THROWS_AS(driver.begin(FrameInfo{0, 10, spreadPalette(4)}), Error);
  driver.begin(FrameInfo{4, 2, spreadPalette(4)});
  const PaletteIndex good[] = {0, 1, 2, 3};
  CHECK_THROWS_AS(driver.row(1, good), Error);  // row 0 must come first
  const PaletteIndex bad[] = {0, 1, 9, 2};
  CHECK_THROWS_AS(driver.row(0, bad), Error);
}

TEST_CASE("the driver reports stream size and transmit time at the profile's baud") {
  Tek4125Profile profile;
  profile.baud = 9600;
  MemorySink sink;
  Tek4125Driver driver(sink, profile);
  sendImage(driver, noise(64, 64, 200, 1u));
  CHECK(driver.stats().bytes == sink.bytesWritten());
  CHECK(driver.stats().seconds == Approx(static_cast<double>(sink.bytesWritten()) * 10.0 / 9600.0));
  CHECK(driver.stats().rasterWrites + driver.stats().runLengthWrites >= 64);
}
