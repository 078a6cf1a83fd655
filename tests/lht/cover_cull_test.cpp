// The rasterizer's cull (lht/raster/object_cover.hpp, lht/raster/cover_cull.hpp) may only
// skip pairs that miss: with and without a cover the hit lists must be the
// same, double for double, while the cover traces fewer segments.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "lht/raster/cover_cull.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/object_cover.hpp"
#include "lht/raster/rasterize.hpp"
#include "lht/raster/thesis_table1.hpp"
#include "render/scene/builtin_leaves.hpp"
#include "render/scene/scene.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "tests/support/quiet_raster.hpp"

using namespace lattice;
using namespace lattice::lht;

using lattice::testing::quietRaster;

namespace {

// Rasterizes `object` with and without its cover and requires the same
// answer; returns the segments traced without and with it.
std::pair<std::uint64_t, std::uint64_t> requireSameTable(const LatticeObject& object, double lambda,
                                                         double oversample, unsigned threads = 1) {
  REQUIRE(object.cover);
  const LatticeBox box(object.bounds, lambda, oversample);
  const RasterResult plain = rasterize(box, *object.primitive, quietRaster(1));
  const RasterResult culled = rasterize(box, *object.primitive, &*object.cover, quietRaster(threads));
  REQUIRE(culled.stats.pairs == plain.stats.pairs);
  REQUIRE(culled.stats.hits == plain.stats.hits);
  REQUIRE(culled.stats.distinctPairs == plain.stats.distinctPairs);
  REQUIRE(culled.hits.size() == plain.hits.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < plain.hits.size(); ++k) {
    const RasterHit& a = plain.hits[k];
    const RasterHit& b = culled.hits[k];
    if (!(a.in == b.in && a.out == b.out && a.s == b.s && a.normal == b.normal)) ++differing;
  }
  REQUIRE(differing == 0);
  return {plain.stats.traced, culled.stats.traced};
}

CoverCull cullOf(const ObjectCover& cover) { return CoverCull(cover, {10, 10, 10}); }

NodeDesc leaf(LeafDescPtr desc, const Mat4d& transform = Mat4d(1.0)) {
  NodeDesc node = NodeDesc::makeLeaf(std::move(desc));
  node.transform = transform;
  return node;
}

}  // namespace

TEST_CASE("cover cull: Table 1's shapes rasterize to the same hits with far fewer traces") {
  for (const Table1Row& row : table1Rows()) {
    // The long line at f_lat 2 and the hair at f_lat 2 take seconds: their
    // f_lat 1 rows and the other shapes cover the same code.
    if (row.oversample > 1 && row.thesisPairs > 1000000) continue;
    INFO(row.object << " f_lat " << row.oversample);
    const auto [plain, culled] = requireSameTable(row.make(), 1.0, row.oversample);
    CHECK(culled < plain);
    CHECK(culled > 0);
  }
}

TEST_CASE("cover cull: any thread count gives the same hits") {
  const LatticeObject hook = polylineObject(hookPoints(), 0.5, "hook");
  requireSameTable(hook, 1.0, 2.0, 2);
  requireSameTable(hook, 1.0, 2.0, 3);
}

TEST_CASE("cover cull: a CSG object under rotations and a non-uniform scale keeps its hits") {
  // A union of: a capsule rotated and stretched unevenly (its cover's radius
  // grows by the largest stretch), a torus cut by a half-space (an
  // intersection covered by its bounded operand), and a polyline with a ball
  // taken out (a difference covered by its first operand).
  const Mat4d stretched = glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.1)) *
                          glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 2, 3))) *
                          glm::scale(Mat4d(1.0), Vec3d(1.0, 1.6, 0.8));
  NodeDesc capsule = leaf(makeCapsuleLeafDesc(0.25, 1.5), stretched);
  NodeDesc cut = NodeDesc::makeOperation(
      NodeDesc::Kind::Intersection,
      {leaf(makeQuarticLeafDesc(torus(0.9, 0.25), "torus"),
            glm::rotate(Mat4d(1.0), 0.4, Vec3d(1, 0, 0))),
       leaf(makeQuarticLeafDesc(halfSpace(Vec3d(0, 0, 1), 0.1), "half-space"))});
  NodeDesc holed = NodeDesc::makeOperation(
      NodeDesc::Kind::Difference,
      {leaf(makePolylineLeafDesc({Vec3d(-1, -1, 0.5), Vec3d(0, -0.5, 1.2), Vec3d(1, -1, 0.8)}, 0.2)),
       leaf(makeQuarticLeafDesc(sphere(0.3), "ball"), glm::translate(Mat4d(1.0), Vec3d(0, -0.5, 1.2)))});
  const NodeDesc object =
      NodeDesc::makeOperation(NodeDesc::Kind::Union, {std::move(capsule), std::move(cut), std::move(holed)});
  const LatticeObject solid = sceneObject(object, "test object");
  REQUIRE_FALSE(solid.cover->unbounded);
  CHECK(solid.cover->capsules.size() == 3);  // the capsule and the polyline's two
  CHECK(solid.cover->boxes.size() == 1);     // the torus's box, not the half-space's
  const auto [plain, culled] = requireSameTable(solid, 0.25, 1.0);
  CHECK(culled < plain);
}

TEST_CASE("cover cull: covers of set operations and transforms") {
  const NodeDesc plane = leaf(makeQuarticLeafDesc(halfSpace(Vec3d(0, 0, 1), 0.0), "plane"));
  CHECK(coverOf(plane, Mat4d(1.0)).unbounded);
  // A similarity scales the radius by its scale.
  const Mat4d similar = glm::rotate(Mat4d(1.0), 1.1, glm::normalize(Vec3d(3, -1, 2))) *
                        glm::scale(Mat4d(1.0), Vec3d(2.0));
  const ObjectCover scaled = coverOf(leaf(makeCapsuleLeafDesc(0.5, 3.0), similar), Mat4d(1.0));
  REQUIRE(scaled.capsules.size() == 1);
  CHECK(scaled.capsules[0].radius == Approx(1.0).epsilon(1e-9));
  CHECK(glm::length(scaled.capsules[0].b - scaled.capsules[0].a) == Approx(6.0));
  // A difference lies inside its first operand; an empty union covers nothing.
  const NodeDesc minus = NodeDesc::makeOperation(
      NodeDesc::Kind::Difference, {leaf(makeCapsuleLeafDesc(0.5, 1.0)), plane});
  const ObjectCover difference = coverOf(minus, Mat4d(1.0));
  CHECK_FALSE(difference.unbounded);
  CHECK(difference.capsules.size() == 1);
  const ObjectCover none = coverOf(NodeDesc::makeOperation(NodeDesc::Kind::Union, {}), Mat4d(1.0));
  CHECK(none.capsules.empty());
  CHECK(none.boxes.empty());
  CHECK_FALSE(none.unbounded);
}

TEST_CASE("cover cull: lines are culled only beyond the margin") {
  ObjectCover cover;
  cover.capsules.push_back({Vec3d(2, 2, 2), Vec3d(2, 2, 6), 1.0});
  cover.boxes.push_back({Vec3d(6, 6, 6), Vec3d(7, 7, 7)});
  const CoverCull cull(cover, {10, 10, 10});
  const double m = kCoverMargin;
  // Lines parallel to x passing the capsule's axis at 1 + distance.
  for (const double z : {2.0, 4.0, 6.0}) {
    CHECK(cull.mayTouch(Vec3d(0, 3.0 + 0.5 * m, z), Vec3d(10, 3.0 + 0.5 * m, z)));
    CHECK_FALSE(cull.mayTouch(Vec3d(0, 3.0 + 2 * m, z), Vec3d(10, 3.0 + 2 * m, z)));
  }
  // Past the end of the axis the round cap decides: diagonal distance.
  const double beyond = 1.0 / std::sqrt(2.0);
  CHECK(cull.mayTouch(Vec3d(0, 2 + beyond, 6 + beyond), Vec3d(10, 2 + beyond, 6 + beyond)));
  CHECK_FALSE(cull.mayTouch(Vec3d(0, 2 + beyond + 2 * m, 6 + beyond + 2 * m),
                            Vec3d(10, 2 + beyond + 2 * m, 6 + beyond + 2 * m)));
  // The box: a line along its edge touches, one just outside the margin does not.
  CHECK(cull.mayTouch(Vec3d(0, 7, 7), Vec3d(10, 7, 7)));
  CHECK_FALSE(cull.mayTouch(Vec3d(0, 7 + 2 * m, 7), Vec3d(10, 7 + 2 * m, 7)));
  // The fan from a face point answers as the line test does for every exit point.
  CoverCull::Fan fan;
  const LatticeBox box(std::array<int, 3>{10, 10, 10}, 1.0, 1.0, Vec3d(0.0));
  std::size_t touching = 0;
  for (const LatticePoint& p : box.boundaryPoints()) {
    const std::uint8_t facesP = box.facesOf(p);
    cull.aim(p.toVec(), facesP, fan);
    for (const LatticePoint& q : box.boundaryPoints()) {
      const std::uint8_t facesQ = box.facesOf(q);
      if (facesP & facesQ) continue;
      const bool line = cull.mayTouch(p.toVec(), q.toVec());
      const bool fanned = cull.mayTouch(fan, q.toVec(), facesQ);
      // The cover lies inside the box, where the line is the segment.
      REQUIRE(line == fanned);
      if (fanned) ++touching;
    }
  }
  CHECK(touching > 0);
}

TEST_CASE("cover cull: a cover of too many pieces culls nothing") {
  ObjectCover cover;
  for (std::size_t k = 0; k <= kMaxCoverPieces; ++k) cover.capsules.push_back({Vec3d(5, 5, 1), Vec3d(5, 5, 2), 0.5});
  CHECK(cullOf(cover).mayTouch(Vec3d(0, 0, 9), Vec3d(10, 0, 9)));
  cover.capsules.pop_back();
  CHECK_FALSE(cullOf(cover).mayTouch(Vec3d(0, 0, 9), Vec3d(10, 0, 9)));
}
