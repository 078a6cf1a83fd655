// The example scenes end to end through the Tektronix 4027 output chain:
// renderer -> pipeline (8 colours) -> driver -> bytes -> emulator. The
// emulated picture must reproduce the quantized image pixel for pixel: the
// driver renumbers palette indices to paint pots, so the test checks that
// index -> pot is one-to-one over the picture, and that every pot shows its
// index's colour within the HLS round trip (kHlsRoundTripMaxDelta, see
// docs/tek4027.md). Stream and picture are goldens (docs/testing.md).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "devices/device_table.hpp"
#include "devices/tek4027/tek4027_hls.hpp"
#include "devices/tek4027/tek4027_profile.hpp"
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
using namespace lattice::tek4027;

namespace {

struct SceneCase {
  const char* scene;  // file under scenes/
  int width, height;
  Dither dither;
};

// The strict (default) goldens keep the plain names; the compact profile's
// carry a `_compact` suffix.
std::string stemOf(const SceneCase& c, const std::string& profileName) {
  std::string name = c.scene;
  name = name.substr(0, name.find('.'));
  return fmt::format("tek4027/scenes/{}_{}x{}{}{}", name, c.width, c.height,
                     c.dither == Dither::FloydSteinberg ? "_fs" : "", profileName == "strict" ? "" : "_" + profileName);
}

void runSceneCase(const SceneCase& c, const std::string& profileName) {
  INFO("scene " << c.scene << " " << c.width << "x" << c.height << ", profile " << profileName);
  const SceneDesc scene = testing::loadExampleScene(c.scene);
  Renderer<double> renderer = testing::makeTestRenderer(scene, c.width, c.height);

  // The device table with the one --set a user would type.
  const devices::Device device = devices::makeDevice("tek4027", {"profile=" + profileName});
  const Tek4027Profile profile = tek4027Preset(profileName);

  PipelineOptions options;
  options.progress = false;
  options.quantize.dither = c.dither;

  IndexedImageSink quantizedSink(profile.colors);
  runPipeline(renderer, quantizedSink, options);
  const IndexedImage& quantized = quantizedSink.image();
  REQUIRE(quantized.width == c.width);
  REQUIRE(quantized.height == c.height);
  REQUIRE(quantized.colormap.size() <= 8);

  MemorySink stream;
  auto driver = device.makeDriver(stream);
  runPipeline(renderer, driver->sink(), options);
  REQUIRE(driver->stats().bytes == stream.data().size());

  // One byte at a time: the 4027 parser must not depend on the chunking.
  auto decoder = device.makeEmulator();
  for (std::uint8_t b : stream.data()) decoder->feed(std::span<const std::uint8_t>(&b, 1));
  decoder->finish();
  CHECK(decoder->report().malformed == 0);
  CHECK(decoder->report().unknownCommands == 0);
  const IndexedImage& screen = decoder->image();
  REQUIRE(screen.width == profile.width);
  REQUIRE(screen.height == profile.height);

  // The picture sits at the top left of the graphics area (docs/tek4027.md);
  // everything else keeps the erase colour, the background pot.
  std::vector<int> potOf(256, -1), indexOf(256, -1);
  long notOneToOne = 0, wrongColours = 0, outsideDrawn = 0;
  RgbImage picture(c.width, c.height);
  for (int y = 0; y < screen.height; ++y)
    for (int x = 0; x < screen.width; ++x) {
      const int pot = screen.at(x, y);
      if (x >= c.width || y >= c.height) {
        outsideDrawn += pot != profile.backgroundPot;
        continue;
      }
      const int index = quantized.at(x, y);
      if (potOf[index] < 0) potOf[index] = pot;
      if (indexOf[pot] < 0) indexOf[pot] = index;
      notOneToOne += potOf[index] != pot || indexOf[pot] != index;
      const Rgb8 want = quantized.colormap[static_cast<std::size_t>(index)], shown = screen.colorAt(x, y);
      const int delta = std::max({std::abs(want.r - shown.r), std::abs(want.g - shown.g), std::abs(want.b - shown.b)});
      wrongColours += delta > kHlsRoundTripMaxDelta;
      picture.pixel(x, y)[0] = shown.r;
      picture.pixel(x, y)[1] = shown.g;
      picture.pixel(x, y)[2] = shown.b;
    }
  CHECK(notOneToOne == 0);
  CHECK(wrongColours == 0);
  CHECK(outsideDrawn == 0);

  const std::string stem = stemOf(c, profileName);
  testing::checkGoldenBytes(stem + ".tek", stream.data());
  testing::checkGoldenPng(stem + ".png", picture);
}

}  // namespace

TEST_CASE("scene goldens: the example scenes in eight paint pots") {
  const SceneCase cases[] = {
      {"sphere-hole.toml", 64, 64, Dither::None},
      {"torus-floor.toml", 80, 60, Dither::None},
      {"thesis-camera.toml", 64, 64, Dither::None},
      {"hook.toml", 64, 64, Dither::None},
  };
  for (const std::string& profile : tek4027PresetNames())
    for (const SceneCase& c : cases) runSceneCase(c, profile);
}

TEST_CASE("scene goldens: a Floyd-Steinberg dithered frame in eight pots") {
  for (const std::string& profile : tek4027PresetNames())
    runSceneCase({"torus-floor.toml", 80, 60, Dither::FloydSteinberg}, profile);
}
