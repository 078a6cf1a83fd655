// The exit candidates (lht/raster/exit_candidates.hpp) must name exactly the
// exit points, and for each exactly the pieces, that the fan's rectangles
// hold on the point's lowest face: what CoverCull::mayTouch reads, point by
// point. The rasterizer visits only these, so a point missed here would be a
// hit missing from the table.
#include <catch2/catch.hpp>

#include <bit>

#include "lht/raster/cover_cull.hpp"
#include "lht/raster/exit_candidates.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/thesis_table1.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

// The pieces whose rectangle on q's lowest face holds q, read as mayTouch reads them.
std::uint64_t piecesHolding(const CoverCull& cull, const CoverCull::Fan& fan, const LatticePoint& q, std::uint8_t facesQ) {
  const int face = std::countr_zero(static_cast<unsigned>(facesQ));
  const Vec3d at = q.toVec();
  const double u = at[kAcrossAxes[face / 2][0]], v = at[kAcrossAxes[face / 2][1]];
  std::uint64_t mask = 0;
  for (std::size_t k = 0; k < cull.pieces(); ++k) {
    const double* rect = &fan.rects[(static_cast<std::size_t>(face) * cull.pieces() + k) * 4];
    if (u >= rect[0] && u <= rect[1] && v >= rect[2] && v <= rect[3]) mask |= std::uint64_t(1) << k;
  }
  return mask;
}

// Every entry point of the box: the candidates against the rectangles and
// the exact answer point by point; returns the candidates seen.
std::size_t requireSameAsPointByPoint(const LatticeBox& box, const ObjectCover& coverInLattice) {
  const CoverCull cull(coverInLattice, box.cells());
  REQUIRE(cull.active());
  const std::vector<LatticePoint> points = box.boundaryPoints();
  ExitCandidates exits(box, points);
  std::vector<ExitCandidates::Candidate> candidates;
  CoverCull::Fan fan;
  std::size_t seen = 0;
  for (const LatticePoint& p : points) {
    const std::uint8_t facesP = box.facesOf(p);
    cull.aim(p.toVec(), facesP, fan);
    exits.collect(cull, fan, facesP, candidates);
    std::size_t next = 0;
    for (std::size_t j = 0; j < points.size(); ++j) {
      const std::uint8_t facesQ = box.facesOf(points[j]);
      const bool candidate = next < candidates.size() && candidates[next].point == j;
      const std::uint64_t pieces = candidate ? candidates[next++].pieces : 0;
      if (facesP & facesQ) continue;  // never traced, whether a candidate or not
      INFO("p (" << int(p.x) << "," << int(p.y) << "," << int(p.z) << ") q (" << int(points[j].x) << ","
                 << int(points[j].y) << "," << int(points[j].z) << ")");
      REQUIRE(pieces == piecesHolding(cull, fan, points[j], facesQ));
      REQUIRE(cull.mayTouch(fan, points[j].toVec(), pieces) == cull.mayTouch(fan, points[j].toVec(), facesQ));
      seen += candidate;
    }
    REQUIRE(next == candidates.size());  // in increasing order, none left over
  }
  return seen;
}

}  // namespace

TEST_CASE("exit candidates: the hook's fans name the points and pieces their rectangles hold") {
  const LatticeObject hook = polylineObject(hookPoints(), 0.5, "hook");
  for (const double oversample : {1.0, 2.0}) {
    const LatticeBox box(hook.bounds, 1.0, oversample);
    CHECK(requireSameAsPointByPoint(box, hook.cover->mapped(box.objectToLattice())) > 0);
  }
}

TEST_CASE("exit candidates: rectangles over edges, corners and whole faces, with boxes among the pieces") {
  // A capsule reaching within a cell of the faces (rectangles cut off at the
  // sliver, or the whole face) and a box, in a box of unequal sides.
  ObjectCover cover;
  cover.capsules.push_back({Vec3d(0.6, 0.6, 0.7), Vec3d(6.2, 2.4, 10.3), 0.4});
  cover.boxes.push_back({Vec3d(3.0, 1.0, 4.0), Vec3d(5.5, 2.2, 5.0)});
  const LatticeBox box(std::array<int, 3>{7, 3, 11}, 1.0, 1.0, Vec3d(0.0));
  CHECK(requireSameAsPointByPoint(box, cover) > 0);
}
