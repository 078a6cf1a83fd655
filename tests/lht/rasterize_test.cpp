// Every stored entry must be the exact intersection, up to the entry's
// quantization; every pair that misses must be absent.
#include <catch2/catch.hpp>

#include <cmath>

#include "lht/raster/lattice_object.hpp"
#include "lht/raster/rasterize.hpp"
#include "lht/table/hash_table.hpp"
#include "tests/support/quiet_raster.hpp"

using namespace lattice;
using namespace lattice::lht;

using lattice::testing::quietRaster;

namespace {

// The reference: a sphere against a segment in closed form (independent of
// the render module's root solver), with tangents counted as hits.
struct Reference {
  bool hit = false;
  double s = 0.0;
  Vec3d normal{};
};
Reference sphereReference(const Vec3d& centre, double radius, const Vec3d& a, const Vec3d& b) {
  const Vec3d d = b - a, w = a - centre;
  const double dd = glm::dot(d, d), wd = glm::dot(w, d), ww = glm::dot(w, w);
  const double disc = wd * wd - dd * (ww - radius * radius);
  Reference r;
  if (disc < -1e-9 * dd * dd) return r;
  r.s = (-wd - std::sqrt(std::max(0.0, disc))) / dd;
  if (r.s < 0.0 || r.s > 1.0) return r;
  r.hit = true;
  r.normal = glm::normalize(w + d * r.s);
  return r;
}

}  // namespace

TEST_CASE("rasterize: a sphere's table holds exactly its hits, each within quantization") {
  for (double oversample : {1.0, 2.0, 3.0}) {
    INFO("f_lat " << oversample);
    const LatticeObject sphere = sphereObject(0.5);
    const LatticeBox box(sphere.bounds, 1.0, oversample);
    const RasterResult raster = rasterize(box, *sphere.primitive, quietRaster());
    const LatticeHashTable table(raster.hits);
    REQUIRE(table.entryCount() == raster.hits.size());
    const Vec3d centre = transformPoint(box.objectToLattice(), Vec3d(0.0));
    const double radius = 0.5 * oversample;  // in cells
    const auto points = box.boundaryPoints();
    std::size_t found = 0, maxSError = 0;
    double worstS = 0.0, worstN = 0.0;
    for (const LatticePoint& a : points)
      for (const LatticePoint& b : points) {
        if (a == b) continue;
        const Reference ref = sphereReference(centre, radius, a.toVec(), b.toVec());
        const auto entry = table.find(a, b);
        REQUIRE(entry.has_value() == ref.hit);
        if (!entry) continue;
        ++found;
        worstS = std::max(worstS, std::abs(entry->s - ref.s));
        for (int c = 0; c < 3; ++c) worstN = std::max(worstN, std::abs(entry->normal[c] - ref.normal[c]));
      }
    (void)maxSError;
    CHECK(found == raster.hits.size());
    // Rounding to the nearest step: s within half of 1/255, each normal
    // component within 1/127 (half a step, plus what renormalizing moves it).
    CHECK(worstS <= 0.5 / 255.0 + 1e-6);
    CHECK(worstN <= 1.0 / 127.0);
  }
}

TEST_CASE("rasterize: capsule hits agree with the exact intersector, tangents included") {
  const LatticeObject capsule = capsuleObject(0.5, 3.0);
  const LatticeBox box(capsule.bounds, 1.0, 2.0);
  const RasterResult raster = rasterize(box, *capsule.primitive, quietRaster());
  REQUIRE(!raster.hits.empty());
  const Mat4d toObject = box.latticeToObject();
  std::size_t grazing = 0;
  for (const RasterHit& hit : raster.hits) {
    const Vec3d a = hit.in.toVec(), b = hit.out.toVec();
    // The hit point lies on the capsule's surface: distance to the axis segment == radius.
    const Vec3d p = transformPoint(toObject, a + (b - a) * hit.s);
    const double z = std::clamp(p.z, 0.0, 3.0);
    CHECK(glm::length(p - Vec3d(0, 0, z)) == Approx(0.5).margin(1e-6));
    CHECK(glm::length(hit.normal) == Approx(1.0));
    CHECK(glm::dot(hit.normal, b - a) <= 1e-6 * glm::length(b - a));  // faces the entry point
    Hit<double> direct;
    if (!capsule.primitive->firstHit(Ray<double>{a, b - a}.transformed(toObject), 0.0, 1.0, direct)) {
      ++grazing;  // only a segment that touches the surface may miss the open solid
      CHECK(std::abs(glm::dot(hit.normal, glm::normalize(b - a))) < 1e-3);
    } else {
      CHECK(direct.t == Approx(hit.s).margin(1e-6));
    }
  }
  INFO("grazing segments: " << grazing);
  CHECK(raster.stats.hits >= raster.hits.size());
}

TEST_CASE("rasterize: the result does not depend on the number of threads") {
  const LatticeObject capsule = capsuleObject(0.5, 2.0);
  const LatticeBox box(capsule.bounds, 1.0, 2.0);
  const RasterResult one = rasterize(box, *capsule.primitive, quietRaster(1));
  const RasterResult two = rasterize(box, *capsule.primitive, quietRaster(2));
  CHECK(one.stats.pairs == two.stats.pairs);
  CHECK(one.stats.hits == two.stats.hits);
  REQUIRE(one.hits.size() == two.hits.size());
  for (std::size_t i = 0; i < one.hits.size(); ++i) {
    CHECK(one.hits[i].in == two.hits[i].in);
    CHECK(one.hits[i].out == two.hits[i].out);
    CHECK(one.hits[i].s == two.hits[i].s);
  }
  CHECK(one.stats.pairs == box.pairCountEq13());
  // Most pairs are provable misses that are never traced.
  CHECK(one.stats.traced < one.stats.distinctPairs);
}

TEST_CASE("rasterize: the hits read as one sequence, in order and by number, like the lists they were made in") {
  std::vector<std::vector<RasterHit>> lists(4);
  for (int n = 0; n < 7; ++n) {
    RasterHit h;
    h.in = {static_cast<std::uint8_t>(n), 0, 0};
    h.s = 0.1 * n;
    lists[n < 3 ? 0 : 2].push_back(h);  // lists 1 and 3 stay empty
  }
  const RasterHits hits(std::move(lists));
  REQUIRE(hits.size() == 7);
  int k = 0;
  for (const RasterHit& h : hits) {
    CHECK(h.in.x == k);
    CHECK(hits[static_cast<std::size_t>(k)].in.x == k);
    ++k;
  }
  CHECK(k == 7);
  CHECK(hits.flat().size() == 7);
  CHECK(hits.bytes() >= 7 * sizeof(RasterHit));
  const RasterHits none;
  CHECK(none.begin() == none.end());
  CHECK(none.empty());
}
