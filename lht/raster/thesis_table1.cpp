#include "lht/raster/thesis_table1.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace lattice::lht {

std::vector<Vec3d> spiralPoints() {
  // N_lp = 33698 / 353950 needs a 2 x 3 x 12 lattice: an object 1 x 2 x 11
  // lambda, i.e. a centre line that stays in a plane and wanders 1 lambda
  // sideways over 10 lambda of height. Ours: one period of a sine of
  // amplitude 0.5 lambda, sampled at 11 points.
  std::vector<Vec3d> points;
  for (int k = 0; k <= 10; ++k) {
    const double z = k;
    points.emplace_back(0.0, 0.5 * std::sin(2.0 * std::numbers::pi * z / 10.0 + std::numbers::pi / 2), z);
  }
  return points;
}

std::vector<Vec3d> hookPoints() {
  // Figure 2: three spheres joined by cylinders in a 4 x 2 x 4 lattice (an
  // object 3 x 1 x 3 lambda). Ours is a "J": a vertical shank and a slanted
  // tip. The figure's example ray (1 0 1)-(1 2 3) crosses the shank.
  return {Vec3d(0.5, 0.5, 2.5), Vec3d(0.5, 0.5, 0.5), Vec3d(2.5, 0.5, 1.0)};
}

std::vector<Vec3d> hairPoints() {
  // Plate 5: 10 spheres joined by 9 cylinders. N_lp = 522450 / 6928158 needs
  // a 5 x 14 x 14 lattice (an object 4 x 13 x 13 lambda). Ours curls through
  // a quarter circle of radius 12 lambda while drifting 3 lambda sideways.
  std::vector<Vec3d> points;
  for (int k = 0; k < 10; ++k) {
    const double u = k / 9.0;
    const double theta = 0.5 * std::numbers::pi * u;
    points.emplace_back(3.0 * u * u, 12.0 * std::sin(theta), 12.0 * (1.0 - std::cos(theta)));
  }
  return points;
}

std::vector<Table1Row> table1Rows() {
  std::vector<Table1Row> rows;
  const auto sphere = [] { return sphereObject(0.5); };
  rows.push_back({"sphere radius 0.5", "sphere r=0.5", 1, 2430, 510, true, sphere});
  rows.push_back({"sphere radius 0.5", "sphere r=0.5", 2, 18750, 3486, true, sphere});
  rows.push_back({"sphere radius 0.5", "sphere r=0.5", 3, 72030, 13614, true, sphere});
  const auto line10 = [] { return capsuleObject(0.5, 10.0); };
  const auto line100 = [] { return capsuleObject(0.5, 100.0); };
  rows.push_back({"straight line length 10", "capsule r=0.5, axis 10", 1, 24030, 10766, true, line10});
  rows.push_back({"straight line length 10", "capsule r=0.5, axis 10", 2, 238750, 93614, true, line10});
  rows.push_back({"straight line length 100", "capsule r=0.5, axis 100", 1, 1190430, 570926, true, line100});
  rows.push_back({"straight line length 100", "capsule r=0.5, axis 100", 2, 13018750, 5368334, true, line100});
  const auto spiral = [] { return polylineObject(spiralPoints(), 0.5, "spiral"); };
  rows.push_back({"spiral radius 5 height 10", "planar sine wave, 10 capsules r=0.5", 1, 33698, 11190, false, spiral});
  rows.push_back({"spiral radius 5 height 10", "planar sine wave, 10 capsules r=0.5", 2, 353950, 111804, false, spiral});
  const auto hook = [] { return polylineObject(hookPoints(), 0.5, "hook"); };
  rows.push_back({"Figure 2 hook", "3 spheres + 2 cylinders r=0.5 (a J)", 1, 9950, 3224, false, hook});
  rows.push_back({"Figure 2 hook", "3 spheres + 2 cylinders r=0.5 (a J)", 2, 95742, 30266, false, hook});
  const auto hair = [] { return polylineObject(hairPoints(), 0.5, "hair"); };
  rows.push_back({"hair", "10 spheres + 9 cylinders r=0.5 (curled)", 1, 522450, 100504, false, hair});
  rows.push_back({"hair", "10 spheres + 9 cylinders r=0.5 (curled)", 2, 6928158, 1366229, false, hair});
  return rows;
}

Table1Result computeTable1Row(const Table1Row& row, const RasterOptions& options) {
  const LatticeObject object = row.make();
  const LatticeBox box(object.bounds, 1.0, row.oversample);
  Table1Result result;
  result.cells = box.cells();
  result.stats = rasterize(box, object, options).stats;
  return result;
}

}  // namespace lattice::lht
