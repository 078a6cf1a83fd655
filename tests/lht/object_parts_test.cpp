// A polyline's parts (lht/raster/lattice_object.hpp, render/shapes/polyline_parts.hpp)
// let the rasterizer trace a segment against only the capsules it passes
// near: its tables must be the ones the whole union gives, double for
// double, ties between two capsules entered at the same t included (their
// normals differ in the last bits, and the union's order decides).
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "lht/raster/lattice_object.hpp"
#include "lht/raster/rasterize.hpp"
#include "lht/raster/thesis_table1.hpp"
#include "render/scene/builtin_leaves.hpp"
#include "render/shapes/polyline_parts.hpp"
#include "tests/support/quiet_raster.hpp"

using namespace lattice;
using namespace lattice::lht;

using lattice::testing::quietRaster;

namespace {

// The object rasterized through its parts and through the whole union;
// returns the hits compared.
std::size_t requireSameHits(const LatticeObject& object, double oversample, unsigned threads = 1) {
  REQUIRE(object.parts);
  REQUIRE(object.cover);
  const LatticeBox box(object.bounds, 1.0, oversample);
  const RasterResult whole = rasterize(box, *object.primitive, &*object.cover, nullptr, quietRaster(1));
  const RasterResult parts = rasterize(box, *object.primitive, &*object.cover, &*object.parts, quietRaster(threads));
  REQUIRE(parts.stats.pairs == whole.stats.pairs);
  REQUIRE(parts.stats.hits == whole.stats.hits);
  REQUIRE(parts.stats.traced == whole.stats.traced);
  REQUIRE(parts.hits.size() == whole.hits.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < whole.hits.size(); ++k) {
    const RasterHit& a = whole.hits[k];
    const RasterHit& b = parts.hits[k];
    if (!(a.in == b.in && a.out == b.out && a.s == b.s && a.normal == b.normal)) ++differing;
  }
  CHECK(differing == 0);
  return whole.hits.size();
}

}  // namespace

TEST_CASE("object parts: a polyline's parts are its union's children, one per segment") {
  std::vector<const Primitive<double>*> parts;
  const PrimitivePtr<double> whole = makePolylineNamingParts<double>(hookPoints(), 0.5, Mat4d(1.0), 0, parts);
  REQUIRE(parts.size() == hookPoints().size() - 1);
  // Every ray through the hook: the union's first hit is the nearest of its parts'.
  std::size_t hits = 0;
  const Bounds<double> box = polylineBounds(hookPoints(), 0.5);
  const Vec3d origin = box.hi + (box.hi - box.lo);  // outside, beyond a corner
  for (int k = 0; k < 200; ++k) {
    const Vec3d target = box.lo + (box.hi - box.lo) * Vec3d(0.005 * k, 0.5 + 0.3 * std::sin(k), 0.5 + 0.4 * std::cos(0.7 * k));
    const Ray<double> ray{origin, target - origin};
    Hit<double> expected, best, part;
    const bool hit = whole->firstHit(ray, 0.0, 1.0, expected);
    bool found = false, inside = false;
    for (const Primitive<double>* p : parts)
      if (p->firstEnter(ray, 0.0, found ? best.t : 1.0, part, inside)) best = part, found = true;
    REQUIRE(hit == found);
    if (hit) CHECK(best.t == expected.t);
    hits += hit;
  }
  CHECK(hits > 0);
}

TEST_CASE("object parts: the hair and the hook rasterize through their parts to the whole union's hits") {
  // The hair at f_lat 1 has capsules entered at the same t by some segments.
  CHECK(requireSameHits(polylineObject(hairPoints(), 0.5, "hair"), 1.0) > 0);
  CHECK(requireSameHits(polylineObject(hookPoints(), 0.5, "hook"), 2.0) > 0);
  CHECK(requireSameHits(polylineObject(hookPoints(), 0.5, "hook"), 2.0, 3) > 0);
}

TEST_CASE("object parts: a scene's polyline, placed by its node's transform, has its parts, other nodes none") {
  NodeDesc hair = NodeDesc::makeLeaf(makePolylineLeafDesc(hairPoints(), 0.5));
  hair.transform = glm::translate(Mat4d(1.0), Vec3d(1.5, -2.0, 0.25)) *
                   glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 2, -1)));
  const LatticeObject placed = sceneObject(hair, "placed hair");
  CHECK(requireSameHits(placed, 1.0) > 0);
  const NodeDesc ball = NodeDesc::makeLeaf(makeCapsuleLeafDesc(0.5, 2.0));
  CHECK_FALSE(sceneObject(ball, "capsule").parts);
  CHECK_FALSE(sceneObject(NodeDesc::makeOperation(NodeDesc::Kind::Union, {hair, ball}), "union").parts);
}
