// The example scenes end to end through the Tektronix 4125 output chain, in
// the shared golden harness (tests/support/scene_goldens.hpp): the emulated
// picture must be the quantized image the driver was given, pixel for pixel,
// where the driver placed it, with colours exactly as the colour map's
// 0..100 percent rounding leaves them, and the rest of the screen as ESC FF
// cleared it (index 0).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <string>

#include "devices/gun_percent.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "tests/support/scene_goldens.hpp"

using namespace lattice;
using namespace lattice::quantize;
using namespace lattice::tek4125;

namespace {

void runSceneCase(const char* scene, int width, int height, int planes, Dither dither, const std::string& forms) {
  testing::SceneGoldenCase c;
  c.device = "tek4125";
  c.settings = {fmt::format("planes={}", planes), "profile=" + forms};
  Tek4125Profile profile;
  applyOverrides(profile, c.settings);
  c.scene = scene;
  c.width = width;
  c.height = height;
  c.dither = dither;
  c.colours = profile.maxColors();
  const std::string name = std::string(scene).substr(0, std::string(scene).find('.'));
  c.stem = fmt::format("tek4125/scenes/{}_{}x{}_{}planes{}{}", name, width, height, planes,
                       dither == Dither::FloydSteinberg ? "_fs" : "", forms == "strict" ? "" : "_" + forms);
  c.streamExtension = ".tek";

  testing::ScreenRules rules;
  // Tek y grows upwards: picture row 0 is the screen row just below the top
  // of the placement.
  rules.origin = [profile](const IndexedImage&, int w, int h) {
    const Tek4125Placement place = placePicture(profile, w, h);
    return std::pair{place.left, profile.height - 1 - (place.bottom + h - 1)};
  };
  // The driver loads 0..100 percent a gun; the screen shows it back in 8 bits.
  rules.colourMatches = [](Rgb8 given, Rgb8 shown) {
    return shown == Rgb8{devices::eightOfPercent(devices::percentOf8(given.r)), devices::eightOfPercent(devices::percentOf8(given.g)),
                         devices::eightOfPercent(devices::percentOf8(given.b))};
  };
  rules.background = 0;
  testing::runSceneGolden(c, rules);
}

}  // namespace

TEST_CASE("scene goldens: the example scenes at 8 planes") {
  for (const char* forms : {"strict", "compact"})
    for (const auto& [scene, w, h] : {std::tuple{"sphere-hole.toml", 64, 64}, std::tuple{"torus-floor.toml", 80, 60},
                                      std::tuple{"thesis-camera.toml", 64, 64}, std::tuple{"hook.toml", 64, 64}})
      runSceneCase(scene, w, h, 8, Dither::None, forms);
}

TEST_CASE("scene goldens: 4 planes gives 16 colours through the same chain") {
  for (const char* forms : {"strict", "compact"})
    for (const auto& [scene, w, h] : {std::tuple{"sphere-hole.toml", 64, 64}, std::tuple{"torus-floor.toml", 80, 60}})
      runSceneCase(scene, w, h, 4, Dither::None, forms);
}

TEST_CASE("scene goldens: Floyd-Steinberg dithered frames survive the stream") {
  for (const char* forms : {"strict", "compact"})
    for (int planes : {4, 8}) runSceneCase("torus-floor.toml", 80, 60, planes, Dither::FloydSteinberg, forms);
}
