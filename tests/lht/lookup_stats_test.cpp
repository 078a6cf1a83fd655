// Counting a render's look-ups (lht/leaf/lookup_stats.hpp, `render --lht-stats`):
// exact counts for rays whose pairs are known, the same counts from one
// thread and from two, and no change to the picture.
#include <catch2/catch.hpp>

#include <limits>

#include "lht/leaf/lattice_leaf.hpp"
#include "lht/raster/lattice_object.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"
#include "tests/lht/raster_support.hpp"
#include "tests/support/hair_scene.hpp"

using namespace lattice;
using namespace lattice::lht;

TEST_CASE("lookup stats: a ray through the centre asks two pairs that hit, one along an edge asks one that misses") {
  // A sphere of radius lambda/2: a 2 x 2 x 2 box from -1 to 1, lattice point (1, 1, 1) at the centre.
  const auto lht = lattice::testing::rasterizeObject(sphereObject(0.5), 1.0, 1.0);
  REQUIRE(lht->box.cells() == std::array{2, 2, 2});
  LookupStats stats("ball", lht);
  const PrimitivePtr<double> leaf = makeLatticeLeaf<double>(lht, Mat4d(1.0), 0, true, &stats);
  const double inf = std::numeric_limits<double>::infinity();
  SpanList<double> spans;
  leaf->spans(Ray<double>{Vec3d(-5, 0, 0), Vec3d(1, 0, 0)}, 0.0, inf, spans);
  REQUIRE(spans.size() == 1);
  LookupSummary s = stats.summary();
  CHECK(s.lookups == 2);  // (0,1,1) -> (2,1,1) enters, (2,1,1) -> (0,1,1) leaves
  CHECK(s.hits == 2);
  CHECK(s.misses == 0);
  CHECK(s.distinctPairs == 2);
  CHECK(s.entriesReferenced == 2);
  CHECK(s.nIzReferenced == 2);  // both points on one face each: eq. 1.3 counts each pair once
  CHECK(s.entries == lht->entryCount());
  CHECK(s.nIz == lht->hits);
  // The same ray again: more look-ups, no new pairs.
  spans.clear();
  leaf->spans(Ray<double>{Vec3d(-5, 0, 0), Vec3d(1, 0, 0)}, 0.0, inf, spans);
  // Along the edge y = z = 1 of the box (rounded to (0,2,2) -> (2,2,2)): one look-up, a miss.
  spans.clear();
  leaf->spans(Ray<double>{Vec3d(-5, 0.9, 0.9), Vec3d(1, 0, 0)}, 0.0, inf, spans);
  CHECK(spans.empty());
  s = stats.summary();
  CHECK(s.lookups == 5);
  CHECK(s.hits == 4);
  CHECK(s.misses == 1);
  CHECK(s.distinctPairs == 3);
  CHECK(s.entriesReferenced == 2);
  CHECK(s.pairSpace == 26u * 25u);  // 26 surface points of a 2 x 2 x 2 box
  CHECK(describeLookups(s).find("5 look-ups, 4 hits, 1 misses") != std::string::npos);
}

namespace {

const std::string kScene = [] {
  testing::HairScene scene;
  scene.size = 48;
  scene.hairs = 300;
  return scene.toml();
}();

struct Counted {
  RgbImage image;
  std::vector<LookupSummary> summaries;
};

Counted renderCounted(int threads, bool count) {
  TableSettings tables;
  tables.progress = false;
  if (count) tables.stats = std::make_shared<LookupStatsBook>();
  const SceneWithLattices loaded = parseSceneWithLattices(kScene, "hair.toml", tables);
  RenderSettings settings;
  settings.threads = threads;
  Renderer<double> renderer(loaded.scene, settings);
  Counted out{renderImage(renderer), {}};
  if (count) out.summaries = tables.stats->summaries();
  return out;
}

}  // namespace

TEST_CASE("lookup stats: two render threads count exactly what one does, and counting leaves the picture alone") {
  const Counted one = renderCounted(1, true);
  const Counted two = renderCounted(2, true);
  const Counted plain = renderCounted(2, false);
  REQUIRE(one.summaries.size() == 1);
  REQUIRE(two.summaries.size() == 1);
  const LookupSummary& a = one.summaries[0];
  const LookupSummary& b = two.summaries[0];
  CHECK(a.lookups > 1000);
  CHECK(a.lookups == b.lookups);
  CHECK(a.hits == b.hits);
  CHECK(a.distinctPairs == b.distinctPairs);
  CHECK(a.entriesReferenced == b.entriesReferenced);
  CHECK(a.nIzReferenced == b.nIzReferenced);
  CHECK(a.lookups == a.hits + a.misses);
  CHECK(a.distinctPairs <= a.lookups);
  CHECK(a.entriesReferenced <= a.distinctPairs);
  CHECK(a.entriesReferenced <= a.entries);
  CHECK(a.nIzReferenced <= a.nIz);
  CHECK(a.offSurface == 0);
  CHECK(one.image.rgb == plain.image.rgb);
  CHECK(two.image.rgb == plain.image.rgb);
}
