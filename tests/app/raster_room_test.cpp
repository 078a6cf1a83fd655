// The render's admission of a lattice under a memory budget
// (app/render_budget.hpp rasterizingWithin): the sample of the raster
// estimate is traced only when the worst case (every distinct pair a hit)
// does not fit, and the admission is then what it was with the sample alone.
#include <catch2/catch.hpp>

#include <memory>

#include "app/memory_plan.hpp"
#include "app/render_budget.hpp"
#include "foundation/error.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/raster_estimate.hpp"
#include "loader/lattice_scene_loader.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

const char* const kBeadScene = R"([[lattices]]
name = "bead"
spacing = 1.0
object = { type = "sphere", radius = 8.0 }
[[objects]]
type = "lattice"
lattice = "bead"
)";

// The room a default budget of `budget` bytes leaves: the resident memory is
// counted by the hook itself, so budgets are set relative to it.
std::shared_ptr<const app::RasterRoom> roomOf(std::uint64_t budget) {
  auto room = std::make_shared<app::RasterRoom>();
  room->budget = budget;
  return room;
}

}  // namespace

TEST_CASE("app:raster_room_skips_the_sample_when_every_pair_hitting_fits") {
  const SceneWithLattices loaded = parseSceneWithLattices(kBeadScene, "bead.toml");
  const LatticeDefinition& bead = *loaded.lattices.at(0);
  const LatticeObject object = sphereObject(8.0);
  const LatticeBox box(object.bounds, 1.0, 1.0);
  const auto resident = residentMemory().value_or(ResidentMemory{});
  const std::uint64_t roomy = resident.peak + (std::uint64_t(1) << 30);

  LazyRasterEstimate lazy(box, object, 1);
  const RasterAllowance allowance = app::rasterizingWithin(roomOf(roomy))(bead, lazy, LhtForm::Hashed, LhtPrecision::Thesis);
  CHECK_FALSE(lazy.wasSampled());
  // No more hits than distinct pairs can come: the count never stops it.
  CHECK(allowance.maxHits == lazy.worstCase().distinctPairs);
}

TEST_CASE("app:raster_room_samples_when_the_worst_case_does_not_fit_and_admits_as_the_sample_says") {
  const SceneWithLattices loaded = parseSceneWithLattices(kBeadScene, "bead.toml");
  const LatticeDefinition& bead = *loaded.lattices.at(0);
  const LatticeObject object = sphereObject(8.0);
  const LatticeBox box(object.bounds, 1.0, 1.0);
  const auto tableBytes = [&](std::uint64_t n) {
    return app::expectedTableBytes(LhtForm::Hashed, LhtPrecision::Thesis, n, box.cells());
  };
  const RasterEstimate sampled = estimateRaster(box, object, 1);
  const RasterEstimate worst = worstCaseRaster(box, 1);
  // Beyond the resident memory now, the worst case's need and the sample's.
  const auto margin = [&](const RasterEstimate& e) {
    return tableBytes(e.hits) + e.bytesFor(e.hits);
  };
  REQUIRE(margin(sampled) + (std::uint64_t(1) << 20) < margin(worst));
  const auto resident = residentMemory().value_or(ResidentMemory{});
  // Between the two (the resident memory moves a little while the test runs: a MiB of slack).
  const std::uint64_t between = resident.peak + margin(sampled) + (std::uint64_t(1) << 20);
  REQUIRE(between < resident.current + margin(worst));

  LazyRasterEstimate lazy(box, object, 1);
  const RasterAllowance allowance =
      app::rasterizingWithin(roomOf(between))(bead, lazy, LhtForm::Hashed, LhtPrecision::Thesis);
  CHECK(lazy.wasSampled());
  CHECK(allowance.maxHits >= sampled.hits);
  CHECK(allowance.maxHits < worst.distinctPairs);

  // Below the sample's need: refused before any work, naming the sample.
  LazyRasterEstimate refused(box, object, 1);
  try {
    app::rasterizingWithin(roomOf(resident.peak + margin(sampled) / 2))(bead, refused, LhtForm::Hashed,
                                                                         LhtPrecision::Thesis);
    FAIL("the lattice was admitted");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK_THAT(e.what(), Catch::Contains("sampled") && Catch::Contains("rasterizing it would take about"));
  }
  CHECK(refused.wasSampled());
}
