// The example scenes through the simulated Apollo display: renderer ->
// pipeline -> the journal driver -> GPR framebuffer. The picture in the middle of the
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
#include "tests/support/scene_goldens.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::quantize;
using namespace lattice::apollo;

namespace {

const char* ditherName(Dither d) {
  switch (d) {
    case Dither::FloydSteinberg: return "_fs";
    case Dither::Bayer: return "_bayer";
    case Dither::None: break;
  }
  return "";
}

// Through the device table's journal driver and its replaying emulator, in
// the shared golden harness (tests/support/scene_goldens.hpp); the journal
// itself is not a golden, the screen is.
void runSceneCase(const char* scene, int width, int height, const std::string& profileName, Dither dither) {
  const ApolloProfile profile = apolloProfileByName(profileName);
  testing::SceneGoldenCase c;
  c.device = "apollo";
  c.settings = {"profile=" + profileName};
  c.scene = scene;
  c.width = width;
  c.height = height;
  c.dither = dither;
  c.colours = profile.colorMapEntries();
  const std::string name = std::string(scene).substr(0, std::string(scene).find('.'));
  c.stem = fmt::format("apollo_sim/scenes/{}_{}x{}_{}{}", name, width, height, profileName, ditherName(dither));
  testing::ScreenRules rules;
  // Centred, odd leftovers to the right and bottom (ApolloDriver::begin).
  rules.origin = [](const IndexedImage& screen, int w, int h) {
    return std::pair{(screen.width - w) / 2, (screen.height - h) / 2};
  };
  rules.sameIndices = true;  // the sink loads the palette in order, so even the indices agree
  testing::runSceneGolden(c, rules);
}

}  // namespace

TEST_CASE("scene goldens: the example scenes on a DN660") {
  for (const auto& [scene, w, h] : {std::tuple{"sphere-hole.toml", 64, 64}, std::tuple{"torus-floor.toml", 80, 60},
                                    std::tuple{"thesis-camera.toml", 64, 64}, std::tuple{"hook.toml", 64, 64}})
    runSceneCase(scene, w, h, "dn660", Dither::None);
}

TEST_CASE("scene goldens: 16 colours on a 4-plane DN660, dithered") {
  runSceneCase("torus-floor.toml", 80, 60, "dn660-4", Dither::FloydSteinberg);
  runSceneCase("thesis-camera.toml", 64, 64, "dn660-4", Dither::Bayer);
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
