// The example scenes end to end through the Tektronix 4027 output chain, in
// the shared golden harness (tests/support/scene_goldens.hpp): renderer ->
// pipeline (8 colours) -> driver -> bytes -> emulator. The driver renumbers
// palette indices to paint pots, so the harness checks that index -> pot is
// one-to-one over the picture; every pot shows its index's colour within the
// HLS round trip (kHlsRoundTripMaxDelta, docs/tek4027.md); the picture sits
// at the top left of the graphics area and the rest keeps the background pot.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "devices/tek4027/tek4027_hls.hpp"
#include "devices/tek4027/tek4027_profile.hpp"
#include "tests/support/scene_goldens.hpp"

using namespace lattice;
using namespace lattice::quantize;
using namespace lattice::tek4027;

namespace {

void runSceneCase(const char* scene, int width, int height, Dither dither, const std::string& profileName) {
  const Tek4027Profile profile = tek4027Preset(profileName);
  testing::SceneGoldenCase c;
  c.device = "tek4027";
  c.settings = {"profile=" + profileName};  // the one --set a user would type
  c.scene = scene;
  c.width = width;
  c.height = height;
  c.dither = dither;
  c.colours = profile.colors;
  // The strict (default) goldens keep the plain names; the compact profile's
  // carry a `_compact` suffix.
  const std::string name = std::string(scene).substr(0, std::string(scene).find('.'));
  c.stem = fmt::format("tek4027/scenes/{}_{}x{}{}{}", name, width, height, dither == Dither::FloydSteinberg ? "_fs" : "",
                       profileName == "strict" ? "" : "_" + profileName);
  c.streamExtension = ".tek";
  testing::ScreenRules rules;
  rules.colourMatches = [](Rgb8 want, Rgb8 shown) {
    return std::max({std::abs(want.r - shown.r), std::abs(want.g - shown.g), std::abs(want.b - shown.b)}) <=
           kHlsRoundTripMaxDelta;
  };
  rules.background = profile.backgroundPot;
  testing::runSceneGolden(c, rules);
}

}  // namespace

TEST_CASE("scene goldens: the example scenes in eight paint pots") {
  for (const std::string& profile : tek4027PresetNames())
    for (const auto& [scene, w, h] : {std::tuple{"sphere-hole.toml", 64, 64}, std::tuple{"torus-floor.toml", 80, 60},
                                      std::tuple{"thesis-camera.toml", 64, 64}, std::tuple{"hook.toml", 64, 64}})
      runSceneCase(scene, w, h, Dither::None, profile);
}

TEST_CASE("scene goldens: a Floyd-Steinberg dithered frame in eight pots") {
  for (const std::string& profile : tek4027PresetNames())
    runSceneCase("torus-floor.toml", 80, 60, Dither::FloydSteinberg, profile);
}
