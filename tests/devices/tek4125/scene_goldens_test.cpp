// The example scenes end to end through the Tektronix 4125 output chain:
// renderer -> pipeline -> driver -> bytes -> emulator. The emulated picture
// must be the quantized image the driver was given, pixel for pixel, with
// colours exactly as the colour map's 0..100 percent rounding leaves them;
// the stream and the picture are kept as goldens so any change to either is
// a reviewed diff (scripts/regenerate-goldens.sh, docs/testing.md).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "devices/device_table.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "foundation/byte_sink.hpp"
#include "io/png.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "foundation/indexed_image.hpp"
#include "quantize/run_pipeline.hpp"
#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "tests/support/example_scene.hpp"
#include "tests/support/golden.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::quantize;
using namespace lattice::tek4125;

namespace {

struct SceneCase {
  const char* scene;  // file under scenes/
  int width, height;
  int planes;
  Dither dither;
  const char* forms = "strict";
};

std::string stemOf(const SceneCase& c) {
  std::string name = c.scene;
  name = name.substr(0, name.find('.'));
  return fmt::format("tek4125/scenes/{}_{}x{}_{}planes{}{}", name, c.width, c.height, c.planes,
                     c.dither == Dither::FloydSteinberg ? "_fs" : "",
                     std::string(c.forms) == "strict" ? "" : std::string("_") + c.forms);
}

// Feeds the stream in uneven chunks: a terminal gets it in whatever pieces
// the line delivers, and the decoder must not care.
void feedChunked(StreamDecoder& decoder, const std::vector<std::uint8_t>& bytes) {
  std::size_t at = 0, step = 1;
  while (at < bytes.size()) {
    const std::size_t n = std::min(bytes.size() - at, step);
    decoder.feed(std::span<const std::uint8_t>(bytes).subspan(at, n));
    at += n;
    step = step * 7 % 1021 + 1;
  }
  decoder.finish();
}

void runSceneCase(const SceneCase& c) {
  INFO("scene " << c.scene << " " << c.width << "x" << c.height << " planes " << c.planes << " " << c.forms);
  const SceneDesc scene = testing::loadExampleScene(c.scene);
  Renderer<double> renderer = testing::makeTestRenderer(scene, c.width, c.height);

  const std::vector<std::string> overrides{fmt::format("planes={}", c.planes), fmt::format("profile={}", c.forms)};
  const devices::Device device = devices::makeDevice("tek4125", overrides);
  Tek4125Profile profile;
  applyOverrides(profile, overrides);

  PipelineOptions options;
  options.progress = false;
  options.quantize.dither = c.dither;

  // The quantized image the driver is given (the pipeline is deterministic,
  // so a second run hands the driver the same rows).
  IndexedImageSink quantizedSink(profile.maxColors());
  runPipeline(renderer, quantizedSink, options);
  const IndexedImage& quantized = quantizedSink.image();
  REQUIRE(quantized.width == c.width);
  REQUIRE(quantized.height == c.height);
  REQUIRE(static_cast<int>(quantized.colormap.size()) <= profile.maxColors());

  MemorySink stream;
  auto driver = device.makeDriver(stream);
  runPipeline(renderer, driver->sink(), options);
  REQUIRE(driver->stats().bytes == stream.data().size());

  auto decoder = device.makeEmulator();
  feedChunked(*decoder, stream.data());
  CHECK(decoder->report().malformed == 0);
  CHECK(decoder->report().unknownCommands == 0);
  const IndexedImage& screen = decoder->image();
  REQUIRE(screen.width == profile.width);
  REQUIRE(screen.height == profile.height);

  // Cut the picture out where the driver put it: Tek y grows upwards, so
  // picture row 0 is the screen row just below the top of the placement.
  const Tek4125Placement place = placePicture(profile, c.width, c.height);
  const int top = profile.height - 1 - (place.bottom + c.height - 1);
  REQUIRE(place.left >= 0);
  REQUIRE(top >= 0);
  IndexedImage picture(c.width, c.height, 0);
  picture.colormap = screen.colormap;
  long wrongColours = 0, outsideDrawn = 0;
  for (int y = 0; y < screen.height; ++y)
    for (int x = 0; x < screen.width; ++x) {
      const int px = x - place.left, py = y - top;
      if (px < 0 || py < 0 || px >= c.width || py >= c.height) {
        outsideDrawn += screen.at(x, y) != 0;  // ESC FF cleared the screen to index 0
        continue;
      }
      picture.at(px, py) = screen.at(x, y);
      // The driver loads 0..100 percent a gun; the screen shows it back in 8 bits.
      const Rgb8 given = quantized.colorAt(px, py);
      const Rgb8 expected{eightFromPercent(percentFrom8(given.r)), eightFromPercent(percentFrom8(given.g)),
                          eightFromPercent(percentFrom8(given.b))};
      wrongColours += !(screen.colorAt(x, y) == expected);
    }
  CHECK(wrongColours == 0);
  CHECK(outsideDrawn == 0);

  // Same partition: two pixels share a screen index exactly when they shared
  // a quantized index (the percent rounding could otherwise merge colours).
  std::vector<int> screenOf(256, -1), quantizedOf(256, -1);
  long splitOrMerged = 0;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const int q = quantized.at(x, y), s = picture.at(x, y);
      if (screenOf[q] < 0) screenOf[q] = s;
      if (quantizedOf[s] < 0) quantizedOf[s] = q;
      splitOrMerged += screenOf[q] != s || quantizedOf[s] != q;
    }
  CHECK(splitOrMerged == 0);

  const std::string stem = stemOf(c);
  testing::checkGoldenBytes(stem + ".tek", stream.data());
  testing::checkGoldenPng(stem + ".png", toRgbImage(picture));
}

}  // namespace

TEST_CASE("scene goldens: the example scenes at 8 planes") {
  for (const char* forms : {"strict", "compact"}) {
    const SceneCase cases[] = {
        {"sphere-hole.toml", 64, 64, 8, Dither::None, forms},
        {"torus-floor.toml", 80, 60, 8, Dither::None, forms},
        {"thesis-camera.toml", 64, 64, 8, Dither::None, forms},
        {"hook.toml", 64, 64, 8, Dither::None, forms},
    };
    for (const SceneCase& c : cases) runSceneCase(c);
  }
}

TEST_CASE("scene goldens: 4 planes gives 16 colours through the same chain") {
  for (const char* forms : {"strict", "compact"}) {
    const SceneCase cases[] = {
        {"sphere-hole.toml", 64, 64, 4, Dither::None, forms},
        {"torus-floor.toml", 80, 60, 4, Dither::None, forms},
    };
    for (const SceneCase& c : cases) runSceneCase(c);
  }
}

TEST_CASE("scene goldens: Floyd-Steinberg dithered frames survive the stream") {
  for (const char* forms : {"strict", "compact"}) {
    const SceneCase cases[] = {
        {"torus-floor.toml", 80, 60, 4, Dither::FloydSteinberg, forms},
        {"torus-floor.toml", 80, 60, 8, Dither::FloydSteinberg, forms},
    };
    for (const SceneCase& c : cases) runSceneCase(c);
  }
}
