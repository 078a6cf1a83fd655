#pragma once
// Thesis Table 1 ("some typical lattice intersection calculations"): the
// objects, f_lat values and the published N_lp / N_iz, with our geometry for
// each. Rows the thesis defines fully (sphere, straight lines) must match
// exactly; for the spiral, hook and hair the thesis gives only a sketch, so
// ours are documented stand-ins whose lattice size reproduces the published
// N_lp but whose N_iz is not comparable.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lht/grid/lattice_box.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

struct Table1Row {
  std::string object;    // as the thesis labels it
  std::string geometry;  // ours, in units of lambda
  double oversample = 1.0;
  std::uint64_t thesisPairs = 0;  // N_lp
  std::uint64_t thesisHits = 0;   // N_iz
  bool comparable = true;         // false: the thesis leaves the geometry open
  std::function<LatticeObject()> make;  // lambda = 1
};

std::vector<Table1Row> table1Rows();

// The objects behind the rows (lambda = 1).
std::vector<Vec3d> spiralPoints();
std::vector<Vec3d> hookPoints();
std::vector<Vec3d> hairPoints();

struct Table1Result {
  std::array<int, 3> cells{};
  RasterStats stats;
};
Table1Result computeTable1Row(const Table1Row& row, const RasterOptions& options = {});

}  // namespace lattice::lht
