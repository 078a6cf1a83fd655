// The example scenes through the simulated Apollo display: renderer ->
// pipeline -> ApolloDriver -> GPR framebuffer. The picture in the middle of the
// screen must be the quantized image exactly (the colour map takes 0xRRGGBB,
// 8 bits a gun, so no rounding), the rest of the screen one background index,
// and the picture is kept as a golden (docs/testing.md). Pipeline modes that
// promise the same output (passes and frame) must give the same screen.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <string>

#include "devices/apollo_sim/apollo_output.hpp"
#include "devices/apollo_sim/apollo_profile.hpp"
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
using namespace lattice::apollo;

namespace {

struct SceneCase {
  const char* scene;  // file under scenes/
  int width, height;
  const char* profile;  // apolloProfileByName
  Dither dither;
};

const char* ditherName(Dither d) {
  switch (d) {
    case Dither::FloydSteinberg: return "_fs";
    case Dither::Bayer: return "_bayer";
    case Dither::None: break;
  }
  return "";
}

std::string stemOf(const SceneCase& c) {
  std::string name = c.scene;
  name = name.substr(0, name.find('.'));
  return fmt::format("apollo_sim/scenes/{}_{}x{}_{}{}", name, c.width, c.height, c.profile, ditherName(c.dither));
}

void runSceneCase(const SceneCase& c) {
  INFO("scene " << c.scene << " " << c.width << "x" << c.height << " on " << c.profile);
  const SceneDesc scene = testing::loadExampleScene(c.scene);
  Renderer<double> renderer = testing::makeTestRenderer(scene, c.width, c.height);
  const ApolloProfile profile = apolloProfileByName(c.profile);

  PipelineOptions options;
  options.progress = false;
  options.quantize.dither = c.dither;

  IndexedImageSink quantizedSink(profile.colorMapEntries());
  runPipeline(renderer, quantizedSink, options);
  const IndexedImage& quantized = quantizedSink.image();

  const ApolloScreen result = renderToApollo(renderer, profile, options);
  const IndexedImage& screen = result.screen;
  REQUIRE(screen.width == profile.width);
  REQUIRE(screen.height == profile.height);

  // Centred, odd leftovers to the right and bottom (ApolloDriver::begin).
  const int left = (profile.width - c.width) / 2, top = (profile.height - c.height) / 2;
  const PaletteIndex background = screen.at(0, 0);
  RgbImage picture(c.width, c.height);
  long wrongIndices = 0, wrongColours = 0, outsideDrawn = 0;
  for (int y = 0; y < screen.height; ++y)
    for (int x = 0; x < screen.width; ++x) {
      const int px = x - left, py = y - top;
      if (px < 0 || py < 0 || px >= c.width || py >= c.height) {
        outsideDrawn += screen.at(x, y) != background;
        continue;
      }
      // The sink loads the palette in order, so even the indices agree.
      wrongIndices += screen.at(x, y) != quantized.at(px, py);
      const Rgb8 shown = screen.colorAt(x, y);
      wrongColours += !(shown == quantized.colorAt(px, py));
      picture.pixel(px, py)[0] = shown.r;
      picture.pixel(px, py)[1] = shown.g;
      picture.pixel(px, py)[2] = shown.b;
    }
  CHECK(wrongIndices == 0);
  CHECK(wrongColours == 0);
  CHECK(outsideDrawn == 0);
  testing::checkGoldenPng(stemOf(c) + ".png", picture);
}

}  // namespace

TEST_CASE("scene goldens: the example scenes on a DN660") {
  const SceneCase cases[] = {
      {"sphere-hole.toml", 64, 64, "dn660", Dither::None},
      {"torus-floor.toml", 80, 60, "dn660", Dither::None},
      {"thesis-camera.toml", 64, 64, "dn660", Dither::None},
      {"hook.toml", 64, 64, "dn660", Dither::None},
  };
  for (const SceneCase& c : cases) runSceneCase(c);
}

TEST_CASE("scene goldens: 16 colours on a 4-plane DN660, dithered") {
  const SceneCase cases[] = {
      {"torus-floor.toml", 80, 60, "dn660-4", Dither::FloydSteinberg},
      {"thesis-camera.toml", 64, 64, "dn660-4", Dither::Bayer},
  };
  for (const SceneCase& c : cases) runSceneCase(c);
}

TEST_CASE("scene goldens: passes and frame mode draw the same screen") {
  // A real rendered scene, dithered so every pixel's error feeds the next:
  // any difference in the rows the two modes map would show.
  const SceneDesc scene = testing::loadExampleScene("torus-floor.toml");
  for (const char* name : {"dn660", "dn660-4"}) {
    INFO("profile " << name);
    const ApolloProfile profile = apolloProfileByName(name);
    PipelineOptions passes;
    passes.progress = false;
    passes.quantize.dither = Dither::FloydSteinberg;
    passes.mode = PipelineMode::TwoPass;
    PipelineOptions frame = passes;
    frame.mode = PipelineMode::Frame;

    Renderer<double> r1 = testing::makeTestRenderer(scene, 96, 72);
    Renderer<double> r2 = testing::makeTestRenderer(scene, 96, 72);
    const ApolloScreen a = renderToApollo(r1, profile, passes);
    const ApolloScreen b = renderToApollo(r2, profile, frame);
    // Passes renders every row twice (histogram, then mapping); frame once.
    CHECK(a.report.rowsRendered == 2L * 72);
    CHECK(b.report.rowsRendered == 72L);
    CHECK(a.report.paletteSize == b.report.paletteSize);
    CHECK(a.screen.colormap == b.screen.colormap);
    CHECK(a.screen.pixels == b.screen.pixels);
  }
}
