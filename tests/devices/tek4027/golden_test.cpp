// The stream the driver writes for a small synthetic frame, and what the
// emulator shows for it, against files in tests/golden/tek4027/. A change in
// either is a visible diff to review (scripts/regenerate-goldens.sh).
#include <catch2/catch.hpp>

#include <algorithm>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "io/png.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/support/golden.hpp"

using namespace lattice;

TEST_CASE("golden: rings 48x32 stream and emulated screen") {
  auto img = testing::ringsImage(48, 32);
  MemorySink sink;
  Tek4027Driver driver(sink);
  driver.begin({img.width, img.height, img.colormap});
  for (int y = 0; y < img.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(&img.pixels[static_cast<std::size_t>(y) * img.width], 48));
  driver.end();
  testing::checkGoldenBytes("tek4027/rings-48x32.tek", sink.data());

  Tek4027Decoder decoder;
  decoder.feed(sink.data());
  decoder.finish();
  CHECK(decoder.report().malformed == 0);
  testing::checkGoldenPng("tek4027/rings-48x32-screen.png", toRgbImage(decoder.image()));
}

TEST_CASE("golden: all eight pots, gradient 40x24") {
  auto img = testing::gradientImage(40, 24);
  MemorySink sink;
  Tek4027Driver driver(sink);
  driver.begin({img.width, img.height, img.colormap});
  for (int y = 0; y < img.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(&img.pixels[static_cast<std::size_t>(y) * img.width], 40));
  driver.end();
  testing::checkGoldenBytes("tek4027/gradient-40x24.tek", sink.data());

  Tek4027Decoder decoder;
  decoder.feed(sink.data());
  decoder.finish();
  CHECK(decoder.report().malformed == 0);
  // Crop to the frame: the rest of the screen is the erase colour.
  RgbImage screen = toRgbImage(decoder.image());
  RgbImage frame(img.width, img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) std::copy_n(screen.pixel(x, y), 3, frame.pixel(x, y));
  testing::checkGoldenPng("tek4027/gradient-40x24-frame.png", frame);
}
