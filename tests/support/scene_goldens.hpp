#pragma once
// One golden harness for every device: an example scene rendered, median-cut,
// written by the device's driver from the device table (with the settings a
// user would type after --set) and decoded by the same entry's emulator in
// uneven chunks. The stream and the picture on the emulated screen are kept
// as goldens (docs/testing.md), and the screen is checked against the
// quantized picture the driver was given: where the device puts it, what
// colour it may show for a given one, and what lies around it. A device's
// test is then its table of cases and its ScreenRules. Header-only: only
// test binaries that link the devices, the quantizer and the renderer
// include it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devices/device_table.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/indexed_image.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/support/example_scene.hpp"
#include "tests/support/golden.hpp"

namespace lattice::testing {

struct SceneGoldenCase {
  std::string device;                 // its name in the device table
  std::vector<std::string> settings;  // as --set takes them
  std::string scene;                  // a file under scenes/
  int width = 0, height = 0;
  quantize::Dither dither = quantize::Dither::None;
  int colours = 256;                  // the quantized picture's palette, as the driver's profile allows
  std::string stem;                   // under tests/golden/, without the extension
  std::string streamExtension;        // ".tek", ".six"; empty: the stream is not a golden
};

// Where a device puts the picture on its screen and what it may show there.
struct ScreenRules {
  // The screen pixel of the picture's top-left pixel.
  std::function<std::pair<int, int>(const IndexedImage& screen, int width, int height)> origin =
      [](const IndexedImage&, int, int) { return std::pair{0, 0}; };
  // Whether the screen may show `shown` where the driver was given `given`.
  std::function<bool(Rgb8 given, Rgb8 shown)> colourMatches = [](Rgb8 given, Rgb8 shown) { return given == shown; };
  // The index every screen pixel outside the picture keeps; unset: one
  // index, whichever the first such pixel has.
  std::optional<int> background;
  // The screen shows the quantized indices themselves (not only the same
  // partition of the pixels under other numbers).
  bool sameIndices = false;
};

// A terminal gets a stream in whatever pieces the line delivers: uneven
// chunks, one byte first.
inline void feedChunked(StreamDecoder& decoder, std::span<const std::uint8_t> bytes) {
  std::size_t at = 0, step = 1;
  while (at < bytes.size()) {
    const std::size_t n = std::min(bytes.size() - at, step);
    decoder.feed(bytes.subspan(at, n));
    at += n;
    step = step * 7 % 1021 + 1;
  }
  decoder.finish();
}

inline void runSceneGolden(const SceneGoldenCase& c, const ScreenRules& rules) {
  INFO(c.device << " " << c.scene << " " << c.width << "x" << c.height << ", golden " << c.stem);
  const SceneDesc scene = loadExampleScene(c.scene);
  Renderer<double> renderer = makeTestRenderer(scene, c.width, c.height);
  const devices::Device device = devices::makeDevice(c.device, c.settings);

  quantize::PipelineOptions options;
  options.progress = false;
  options.quantize.dither = c.dither;
  // The quantized picture the driver is given (the pipeline is deterministic,
  // so a second run hands the driver the same rows).
  IndexedImageSink quantizedSink(c.colours);
  quantize::runPipeline(renderer, quantizedSink, options);
  const IndexedImage& quantized = quantizedSink.image();
  REQUIRE(quantized.width == c.width);
  REQUIRE(quantized.height == c.height);

  MemorySink stream;
  auto driver = device.makeDriver(stream);
  quantize::runPipeline(renderer, driver->sink(), options);
  REQUIRE(driver->stats().bytes == stream.data().size());

  auto decoder = device.makeEmulator();
  feedChunked(*decoder, stream.data());
  CHECK(decoder->report().malformed == 0);
  CHECK(decoder->report().unknownCommands == 0);
  // The device's screen; a sixel emulator's is the picture's own size.
  const IndexedImage& screen = decoder->image();
  REQUIRE(screen.width <= std::max(device.width, c.width));
  REQUIRE(screen.height <= std::max(device.height, c.height));

  const auto [left, top] = rules.origin(screen, c.width, c.height);
  REQUIRE(left >= 0);
  REQUIRE(top >= 0);
  REQUIRE(left + c.width <= screen.width);
  REQUIRE(top + c.height <= screen.height);
  std::optional<int> background = rules.background;
  std::vector<int> screenOf(256, -1), quantizedOf(256, -1);
  long wrongColours = 0, splitOrMerged = 0, wrongIndices = 0, outsideDrawn = 0;
  RgbImage picture(c.width, c.height);
  for (int y = 0; y < screen.height; ++y)
    for (int x = 0; x < screen.width; ++x) {
      const int px = x - left, py = y - top, s = screen.at(x, y);
      if (px < 0 || py < 0 || px >= c.width || py >= c.height) {
        if (!background) background = s;
        outsideDrawn += s != *background;
        continue;
      }
      const int q = quantized.at(px, py);
      // Same partition: two pixels share a screen index exactly when they
      // shared a quantized one (a colour rounding could merge them).
      if (screenOf[q] < 0) screenOf[q] = s;
      if (quantizedOf[s] < 0) quantizedOf[s] = q;
      splitOrMerged += screenOf[q] != s || quantizedOf[s] != q;
      wrongIndices += rules.sameIndices && s != q;
      const Rgb8 shown = screen.colorAt(x, y);
      wrongColours += !rules.colourMatches(quantized.colorAt(px, py), shown);
      std::uint8_t* p = picture.pixel(px, py);
      p[0] = shown.r;
      p[1] = shown.g;
      p[2] = shown.b;
    }
  CHECK(wrongColours == 0);
  CHECK(splitOrMerged == 0);
  CHECK(wrongIndices == 0);
  CHECK(outsideDrawn == 0);

  if (!c.streamExtension.empty()) checkGoldenBytes(c.stem + c.streamExtension, stream.data());
  checkGoldenPng(c.stem + ".png", picture);
}

}  // namespace lattice::testing
