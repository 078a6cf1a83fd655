// The sixel goldens (tests/golden/sixel/): streams the driver writes and the
// emulator's pictures of them, for synthetic frames and for example scenes
// rendered through the whole chain (renderer -> median cut at 16 and 256
// colours -> driver -> emulator). The emulated scene must be the quantized
// picture exactly (registers are palette indices). peers_test.cpp and
// xterm_test.cpp decode the same files with libsixel and xterm.
// scripts/regenerate-goldens.sh rewrites them.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "devices/device_table.hpp"
#include "devices/gun_percent.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/devices/sixel/sixel_support.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/support/example_scene.hpp"
#include "tests/support/golden.hpp"
#include "devices/sixel/sixel_forms.hpp"
#include "tests/support/scene_goldens.hpp"

using namespace lattice;
using namespace lattice::sixel;
using namespace lattice::sixel::test;

namespace {

IndexedImage cleanDecode(const std::vector<std::uint8_t>& stream, const SixelProfile& profile) {
  SixelDecoder decoder(profile);
  for (std::uint8_t b : stream) decoder.feed(std::span<const std::uint8_t>(&b, 1));  // chunking must not matter
  decoder.finish();
  CHECK(decoder.report().malformed == 0);
  CHECK(decoder.report().unknownCommands == 0);
  return decoder.image();
}

void checkGoldenPair(const std::string& stem, const IndexedImage& img, const SixelProfile& profile) {
  const auto stream = driveFrame(img, profile);
  testing::checkGoldenBytes("sixel/" + stem + ".six", stream);
  const IndexedImage screen = cleanDecode(stream, profile);
  CHECK(screen.pixels == img.pixels);
  testing::checkGoldenPng("sixel/" + stem + ".png", toRgbImage(screen));
}

}  // namespace

TEST_CASE("golden: synthetic frames at 16 and 256 registers") {
  checkGoldenPair("rings-48x32", testing::ringsImage(48, 32), {});
  checkGoldenPair("gradient-40x23", testing::gradientImage(40, 23), {});
  SixelProfile wide;
  wide.registers = 256;
  checkGoldenPair("noise-64x30-256", patchyNoise(64, 30, 256, 3, 11), wide);
}

TEST_CASE("golden: example scenes through the whole sixel chain") {
  // The shared golden harness (tests/support/scene_goldens.hpp): the screen is
  // the picture itself, its registers the quantized indices, each gun as the
  // register's percent leaves it.
  testing::ScreenRules rules;
  rules.sameIndices = true;
  rules.colourMatches = [](Rgb8 given, Rgb8 shown) {
    return shown == Rgb8{devices::eightOfPercent(devices::percentOf8(given.r)), devices::eightOfPercent(devices::percentOf8(given.g)), devices::eightOfPercent(devices::percentOf8(given.b))};
  };
  for (const auto& [scene, w, h, registers] :
       {std::tuple{"sphere-hole.toml", 64, 64, 16}, std::tuple{"torus-floor.toml", 80, 60, 256},
        std::tuple{"fuzzy-sphere-1000.toml", 96, 96, 256}}) {
    testing::SceneGoldenCase c;
    c.device = "sixel";
    c.settings = {fmt::format("registers={}", registers)};
    c.scene = scene;
    c.width = w;
    c.height = h;
    c.colours = registers;
    const std::string name = std::string(scene).substr(0, std::string(scene).find('.'));
    c.stem = fmt::format("sixel/scenes/{}_{}x{}_{}", name, w, h, registers);
    c.streamExtension = ".six";
    testing::runSceneGolden(c, rules);
  }
}
