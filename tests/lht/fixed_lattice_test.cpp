// A lattice scene rendered in fixed point (--arith fixed) against double:
// the lattice lookup is integer (grid points, the LHT's bytes) in both, so
// the images differ only where Q31.32 rounding moves a ray's box entry or
// exit across a rounding boundary of the grid.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "tests/render/fixed_support.hpp"
#include "tests/support/hair_scene.hpp"

using namespace lattice;

namespace {

// A small fuzzy ball: 200 hairs on a sphere, over a floor.
const std::string kScene = [] {
  testing::HairScene scene;
  scene.size = 64;
  scene.seed = 3;
  scene.fur = true;
  scene.floor = true;
  return scene.toml();
}();

RgbImage render(const SceneDesc& scene, bool fixedPoint, bool full) {
  RenderSettings settings;
  settings.threads = 2;
  settings.build.fullRayTrace = full;
  if (fixedPoint) {
    Renderer<Fixed32> r(scene, settings);
    return renderImage(r);
  }
  Renderer<double> r(scene, settings);
  return renderImage(r);
}

}  // namespace

TEST_CASE("fixed point: a lattice scene matches the double render") {
  const SceneDesc scene = lht::parseSceneWithLattices(kScene, "fuzzy.toml").scene;
  // Measured (docs/fixed-point.md): the lattice render is identical to
  // double's; the full ray trace 46.8 dB, 0.02% of channels off by > 4.
  SECTION("lattices, at every entry precision (each decoded in integers for fixed point)") {
    for (const lht::LhtPrecisionInfo& form : lht::kLhtPrecisions) {
      lht::TableSettings tables;
      tables.precision = form.precision;
      const lht::SceneWithLattices loaded = lht::parseSceneWithLattices(kScene, "fuzzy.toml", tables);
      const testing::FixedVsDouble m =
          testing::compareRenders(render(loaded.scene, true, false), render(loaded.scene, false, false));
      INFO(form.name << ": PSNR " << m.psnr << " dB, channels off by > 4: " << 100 * m.farFraction << "%");
      CHECK(m.psnr > 35.0);
      CHECK(m.farFraction < 0.01);
    }
  }
  SECTION("the full ray trace of the same hairs (capsules: cylinders, spheres, CSG)") {
    const testing::FixedVsDouble m = testing::compareRenders(render(scene, true, true), render(scene, false, true));
    INFO("PSNR " << m.psnr << " dB, channels off by > 4: " << 100 * m.farFraction << "%");
    CHECK(m.psnr > 35.0);
    CHECK(m.farFraction < 0.01);
  }
}

TEST_CASE("fixed point: the lattice leaf's per-pixel code has no floating point") {
#ifndef NDEBUG
  WARN("skipped: the scan needs an optimized build, where Fixed(double) of literals is folded at compile time");
#elif defined(LATTICE_SANITIZED)
  WARN("skipped under the sanitizers: UBSan's float-cast and ASan's checks add code of their own to every function, "
       "so the scan would read instrumentation, not our arithmetic (the g++ build runs it)");
#else
  // The integer helpers the Fixed32 leaf calls per pixel: the hashed and
  // compressed forms' look-ups and the entry decoders of every precision
  // (their names do not say Fixed).
  const std::vector<std::string> integerPath = {"lht::LatticeHashTable::findKey(", "lht::decodePayloadIntegers(",
                                                "lht::decodePayloadFraction(",
                                                "lht::decodeOctahedral(", "lht::CompressedTable::findPayload("};
  const testing::FixedPointScan scan =
      testing::scanFixedPointCode(LATTICE_BINARY_DIR "/lht/liblattice_lht.a", integerPath);
  const auto seen = [&](const std::string& name) {
    return std::any_of(scan.fixedFunctions.begin(), scan.fixedFunctions.end(),
                       [&](const std::string& f) { return f.find(name) != std::string::npos; });
  };
  REQUIRE(seen("LatticeLeaf<lattice::Fixed<32> >::spans"));
  // The queries that skip the span list (first hit, shadow rays) go through locate().
  REQUIRE(seen("LatticeLeaf<lattice::Fixed<32> >::locate("));
  // The blended look-up (--lattice-lookup blend) is scanned too: g++ inlines
  // its corners, blending and table reads into spans.
  REQUIRE(seen("LatticeLeaf<lattice::Fixed<32> >::firstHit("));
  REQUIRE(seen("LatticeLeaf<lattice::Fixed<32> >::anyHit("));
  for (const std::string& f : integerPath) {
    INFO("the scan did not see " << f);
    REQUIRE(seen(f));
  }
  // The detector works: the set-up code (double -> Q31.32 conversions) shows up.
  REQUIRE_FALSE(scan.withFloatingPoint.empty());
  for (const std::string& f : scan.withFloatingPoint) {
    INFO("floating point in " << f);
    CHECK(testing::isSetUpFunction(f));
  }
#endif
}

TEST_CASE("lattice look-ups: blend is at least as close to the full ray trace as thesis, in every arithmetic") {
  const SceneDesc full = lht::parseSceneWithLattices(kScene, "fuzzy.toml").scene;
  const RgbImage reference = render(full, false, true);
  const auto withLookup = [&](lht::LatticeLookup lookup) {
    lht::TableSettings tables;
    tables.lookup = lookup;
    return lht::parseSceneWithLattices(kScene, "fuzzy.toml", tables);
  };
  const lht::SceneWithLattices thesis = withLookup(lht::LatticeLookup::Thesis);
  const lht::SceneWithLattices blend = withLookup(lht::LatticeLookup::Blend);
  const RgbImage thesisImage = render(thesis.scene, false, false);
  const RgbImage blendImage = render(blend.scene, false, false);
  const double thesisPsnr = testing::compareRenders(thesisImage, reference).psnr;
  const double blendPsnr = testing::compareRenders(blendImage, reference).psnr;
  INFO("against the full ray trace: thesis " << thesisPsnr << " dB, blend " << blendPsnr << " dB");
  // The two look-ups really differ (the setting reaches the leaves) ...
  CHECK(testing::compareRenders(blendImage, thesisImage).maxDelta > 0);
  // ... and blend is the closer (measured on Plate 6 at 512x512: docs/lattices.md, "Look-ups").
  CHECK(blendPsnr >= thesisPsnr);
  // Fixed point follows double's blend as closely as it follows the thesis's look-up.
  const testing::FixedVsDouble m = testing::compareRenders(render(blend.scene, true, false), blendImage);
  INFO("fixed vs double, blend: PSNR " << m.psnr << " dB, channels off by > 4: " << 100 * m.farFraction << "%");
  CHECK(m.psnr > 35.0);
  CHECK(m.farFraction < 0.01);
}
