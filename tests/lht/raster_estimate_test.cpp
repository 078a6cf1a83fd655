// What rasterizing a lattice will hold, known before it starts
// (lht/raster/raster_estimate.hpp), and the rasterizer's running count that
// stops it when an estimate was short (RasterOptions::maxHits).
#include <catch2/catch.hpp>

#include <cmath>

#include "foundation/error.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/raster_estimate.hpp"
#include "lht/raster/rasterize.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "loader/table_build.hpp"
#include "tests/support/quiet_raster.hpp"

using namespace lattice;
using namespace lattice::lht;

using lattice::testing::quietRaster;

namespace {

}  // namespace

TEST_CASE("raster estimate: counts the pairs the rasterizer considers, and a small lattice's hits exactly") {
  const LatticeObject sphere = sphereObject(2.0);
  const LatticeBox box(sphere.bounds, 1.0, 1.0);  // 5 x 5 x 5 cells
  const RasterResult raster = rasterize(box, sphere, quietRaster(1));
  const RasterEstimate e = estimateRaster(box, sphere, 1, raster.stats.distinctPairs);  // every pair traced
  CHECK(e.pairs == box.pairCountEq13());
  CHECK(e.pairs == raster.stats.pairs);
  CHECK(e.distinctPairs == raster.stats.distinctPairs);
  CHECK(e.boundaryPoints == box.boundaryPoints().size());
  CHECK(e.sampled == e.distinctPairs);
  CHECK(e.hits == raster.hits.size());
  CHECK(e.bytesFor(e.hits) > e.hits * RasterEstimate::kHitBytes);
}

TEST_CASE("raster estimate: a sampled lattice's hits within a few per cent, the same every run") {
  // A sphere 17 cells a side and a capsule 22 cells long: more pairs than are sampled.
  for (const LatticeObject& object : {sphereObject(8.0), capsuleObject(0.5, 20.0)}) {
    const LatticeBox box(object.bounds, 1.0, 1.0);
    const RasterResult raster = rasterize(box, object, quietRaster(0));
    const RasterEstimate e = estimateRaster(box, object, 0);
    INFO(object.definition << ": " << e.hits << " estimated, " << raster.hits.size() << " rasterized");
    REQUIRE(e.distinctPairs > kEstimateSamples);
    CHECK(e.sampled == kEstimateSamples);
    CHECK(e.distinctPairs == raster.stats.distinctPairs);
    CHECK(std::abs(double(e.hits) - double(raster.hits.size())) <= 0.05 * double(raster.hits.size()));
    CHECK(estimateRaster(box, object, 0).hits == e.hits);
    // The cover's cull (one fan per entry point) only skips certain misses:
    // without a cover every drawn pair is traced, and the same ones hit.
    LatticeObject uncovered = object;
    uncovered.cover.reset();
    const RasterEstimate traced = estimateRaster(box, uncovered, 0);
    CHECK(traced.sampled == e.sampled);
    CHECK(traced.sampledHits == e.sampledHits);
  }
}

TEST_CASE("raster estimate: the worst case counts as the sample does, every distinct pair a hit, and bounds it") {
  for (const LatticeObject& object : {sphereObject(8.0), capsuleObject(0.5, 20.0), sphereObject(2.0)}) {
    const LatticeBox box(object.bounds, 1.0, 1.0);
    for (const unsigned threads : {1u, 2u}) {
      const RasterEstimate sampled = estimateRaster(box, object, threads);
      const RasterEstimate worst = worstCaseRaster(box, threads);
      INFO(object.definition << " on " << threads << " threads");
      CHECK(worst.cells == sampled.cells);
      CHECK(worst.pairs == sampled.pairs);
      CHECK(worst.distinctPairs == sampled.distinctPairs);
      CHECK(worst.boundaryPoints == sampled.boundaryPoints);
      CHECK(worst.fixedBytes == sampled.fixedBytes);
      CHECK(worst.sampled == 0);
      CHECK(worst.hits == worst.distinctPairs);
      REQUIRE(sampled.hits < worst.hits);
      // What the worst case admits, any sample admits: it holds more at every count.
      CHECK(worst.rowBytes > sampled.rowBytes);
      CHECK(worst.bytesFor(worst.hits) > sampled.bytesFor(sampled.hits));
    }
  }
}

TEST_CASE("raster estimate: the lazy estimate traces its sample once, on the first ask") {
  const LatticeObject object = sphereObject(8.0);
  const LatticeBox box(object.bounds, 1.0, 1.0);
  LazyRasterEstimate lazy(box, object, 1);
  CHECK_FALSE(lazy.wasSampled());
  CHECK(lazy.worstCase().hits == worstCaseRaster(box, 1).hits);
  CHECK_FALSE(lazy.wasSampled());
  const RasterEstimate& first = lazy.sampled();
  CHECK(lazy.wasSampled());
  CHECK(first.sampledHits == estimateRaster(box, object, 1).sampledHits);
  CHECK(&lazy.sampled() == &first);
}

TEST_CASE("raster estimate: the same hits on every thread count") {
  // The sample is traced on the rasterizer's threads; which thread traced a
  // pair must not change what was counted, sampled or every pair traced.
  for (const LatticeObject& object : {sphereObject(8.0), capsuleObject(0.5, 20.0), sphereObject(2.0)}) {
    const LatticeBox box(object.bounds, 1.0, 1.0);
    const RasterEstimate one = estimateRaster(box, object, 1);
    REQUIRE(one.sampledHits > 0);
    for (const unsigned threads : {2u, 3u, 8u}) {
      const RasterEstimate many = estimateRaster(box, object, threads);
      INFO(object.definition << " on " << threads << " threads");
      CHECK(many.sampled == one.sampled);
      CHECK(many.sampledHits == one.sampledHits);
      CHECK(many.hits == one.hits);
    }
  }
}

TEST_CASE("rasterize: the running count stops the rasterizer past maxHits, and a limit it meets changes nothing") {
  const LatticeObject sphere = sphereObject(3.0);
  const LatticeBox box(sphere.bounds, 1.0, 1.0);
  for (unsigned threads : {1u, 2u}) {
    INFO(threads << " threads");
    const RasterResult whole = rasterize(box, sphere, quietRaster(threads));
    REQUIRE(whole.hits.size() > 100);
    RasterOptions limited = quietRaster(threads);
    limited.maxHits = whole.hits.size() / 2;
    try {
      rasterize(box, sphere, limited);
      FAIL("the rasterizer passed its limit");
    } catch (const RasterHitLimit& stop) {
      CHECK(stop.hits > limited.maxHits);
      CHECK(stop.pointsDone < stop.points);
      CHECK(stop.points == box.boundaryPoints().size());
    }
    limited.maxHits = whole.hits.size();
    const RasterResult met = rasterize(box, sphere, limited);
    CHECK(met.hits.flat().size() == whole.hits.size());
    CHECK(met.stats.hits == whole.stats.hits);
  }
}

TEST_CASE("raster estimate: a table build asks the admission first, and stops at the count it allows") {
  const SceneWithLattices loaded = parseSceneWithLattices(R"([[lattices]]
name = "bead"
spacing = 1.0
object = { type = "sphere", radius = 3.0 }
[[objects]]
type = "lattice"
lattice = "bead"
)",
                                                          "bead.toml");
  const LatticeDefinition& bead = *loaded.lattices.at(0);
  TableSettings settings;
  settings.progress = false;
  settings.threads = 1;
  const BuiltTable whole = buildLatticeTable(bead, settings);
  const std::uint64_t entries = whole.lht.entryCount();
  REQUIRE(entries > 100);

  RasterEstimate seen;
  settings.admission = [&](const LatticeDefinition& lattice, LazyRasterEstimate& e, LhtForm, LhtPrecision) {
    CHECK(lattice.name == "bead");
    seen = e.sampled();
    return RasterAllowance{entries / 2, "more than the budget allows"};
  };
  try {
    buildLatticeTable(bead, settings);
    FAIL("the build passed its count");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK_THAT(e.what(), Catch::StartsWith("bead.toml:1:1: lattice 'bead': rasterizing stopped at") &&
                             Catch::Contains("more than the budget allows"));
  }
  CHECK(seen.distinctPairs == whole.stats.distinctPairs);

  // A refusal before any work reaches the caller as it was thrown.
  settings.admission = [](const LatticeDefinition&, LazyRasterEstimate&, LhtForm, LhtPrecision) -> RasterAllowance {
    throw Error(ErrorKind::Input, "too large");
  };
  CHECK_THROWS_WITH(buildLatticeTable(bead, settings), Catch::Contains("lattice 'bead': too large"));
}
