// Thesis Table 1: the rows whose geometry the thesis fixes must come out
// exactly, N_lp and N_iz both.
#include <catch2/catch.hpp>

#include "lht/raster/thesis_table1.hpp"
#include "tests/support/quiet_raster.hpp"

using namespace lattice;
using namespace lattice::lht;

using lattice::testing::quietRaster;

namespace {

void checkRow(const Table1Row& row) {
  INFO(row.object << " f_lat=" << row.oversample);
  const Table1Result result = computeTable1Row(row, quietRaster());
  CHECK(result.stats.pairs == row.thesisPairs);
  CHECK(result.stats.hits == row.thesisHits);
}

}  // namespace

TEST_CASE("Table 1: sphere of radius 0.5 lambda at f_lat 1, 2, 3") {
  const auto rows = table1Rows();
  for (int i = 0; i < 3; ++i) {
    REQUIRE(rows[i].object.rfind("sphere", 0) == 0);
    checkRow(rows[i]);
  }
}

TEST_CASE("Table 1: straight line of length 10 lambda at f_lat 1, 2") {
  const auto rows = table1Rows();
  REQUIRE(rows[3].object == "straight line length 10");
  checkRow(rows[3]);
  checkRow(rows[4]);
}

TEST_CASE("Table 1: straight line of length 100 lambda at f_lat 1, 2") {
  const auto rows = table1Rows();
  REQUIRE(rows[5].object == "straight line length 100");
  checkRow(rows[5]);
  checkRow(rows[6]);
}

TEST_CASE("Table 1: our stand-ins for the spiral, hook and hair have the thesis's lattice sizes") {
  // Their N_iz depends on geometry the thesis does not give, but the lattice
  // size (hence N_lp by eq. 1.3) is fixed by the published N_lp.
  for (const Table1Row& row : table1Rows()) {
    if (row.comparable) continue;
    INFO(row.object << " f_lat=" << row.oversample);
    const LatticeObject object = row.make();
    const LatticeBox box(object.bounds, 1.0, row.oversample);
    CHECK(box.pairCountEq13() == row.thesisPairs);
  }
}

TEST_CASE("Table 1: the Figure 2 hook is hit by the figure's example ray") {
  const LatticeObject hook = polylineObject(hookPoints(), 0.5, "hook");
  const LatticeBox box(hook.bounds, 1.0, 1.0);
  REQUIRE(box.cells() == std::array<int, 3>{4, 2, 4});
  const Ray<double> ray =
      Ray<double>{Vec3d(1, 0, 1), Vec3d(1, 2, 3) - Vec3d(1, 0, 1)}.transformed(box.latticeToObject());
  Hit<double> hit;
  CHECK(hook.primitive->firstHit(ray, 0.0, 1.0, hit));
}
