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
#include "quantize/run_pipeline.hpp"
#include "tests/devices/sixel/sixel_support.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/support/example_scene.hpp"
#include "tests/support/golden.hpp"

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
  struct Case {
    const char* scene;
    int width, height, registers;
  };
  for (const Case c : {Case{"sphere-hole.toml", 64, 64, 16}, Case{"torus-floor.toml", 80, 60, 256},
                       Case{"fuzzy-sphere-1000.toml", 96, 96, 256}}) {
    INFO(c.scene << " at " << c.registers << " registers");
    const SceneDesc scene = testing::loadExampleScene(c.scene);
    Renderer<double> renderer = testing::makeTestRenderer(scene, c.width, c.height);
    const devices::Device device = devices::makeDevice("sixel", {fmt::format("registers={}", c.registers)});
    quantize::PipelineOptions options;
    options.progress = false;
    IndexedImageSink quantized(c.registers);
    quantize::runPipeline(renderer, quantized, options);
    MemorySink stream;
    auto driver = device.makeDriver(stream);
    quantize::runPipeline(renderer, driver->sink(), options);
    REQUIRE(driver->stats().bytes == stream.data().size());
    SixelProfile profile;
    profile.registers = c.registers;
    const IndexedImage screen = cleanDecode(stream.data(), profile);
    CHECK(screen.pixels == quantized.image().pixels);
    std::string stem = c.scene;
    stem = fmt::format("scenes/{}_{}x{}_{}", stem.substr(0, stem.find('.')), c.width, c.height, c.registers);
    testing::checkGoldenBytes("sixel/" + stem + ".six", stream.data());
    testing::checkGoldenPng("sixel/" + stem + ".png", toRgbImage(screen));
  }
}
