// A lattice leaf must answer rays like the exact object it was rasterized
// from, within what the lattice's resolution allows.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "lht/leaf/lattice_leaf.hpp"
#include "lht/raster/lattice_object.hpp"
#include "render/shapes/csg.hpp"
#include "render/shapes/composite_shapes.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "tests/lht/raster_support.hpp"

using namespace lattice;
using namespace lattice::lht;
using lattice::testing::rasterizeObject;

namespace {

struct Agreement {
  int rays = 0, bothHit = 0, disagree = 0;
  int farFromSilhouette = 0;  // disagreements where the exact answer is the same a cell around
  double worstT = 0.0;         // |t_lattice - t_exact| where both hit
  double meanNormalDot = 0.0;  // mean n_lattice . n_exact where both hit
};

// A grid of parallel rays along `direction` over the object's box, in world space.
Agreement compare(const Primitive<double>& lattice, const Primitive<double>& exact, const Vec3d& direction,
                  double cell) {
  Agreement a;
  const Bounds<double>& b = exact.bounds();
  const Vec3d centre = b.center();
  const double extent = glm::length(b.hi - b.lo);
  const Vec3d d = glm::normalize(direction);
  const Vec3d u = glm::normalize(glm::cross(d, std::abs(d.x) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0)));
  const Vec3d v = glm::cross(d, u);
  const int n = 64;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3d offset = u * ((i + 0.5) / n - 0.5) * extent + v * ((j + 0.5) / n - 0.5) * extent;
      const Ray<double> ray{centre + offset - d * (2 * extent), d};
      Hit<double> hl, he;
      const bool l = lattice.firstHit(ray, 0.0, 1e30, hl);
      const bool e = exact.firstHit(ray, 0.0, 1e30, he);
      ++a.rays;
      if (l != e) {
        ++a.disagree;
        bool nearSilhouette = false;
        for (int k = 0; k < 8; ++k) {
          const double angle = k * 0.25 * 3.14159265358979;
          const Vec3d shift = (u * std::cos(angle) + v * std::sin(angle)) * cell;
          Hit<double> hs;
          if (exact.firstHit(Ray<double>{ray.origin + shift, d}, 0.0, 1e30, hs) != e) nearSilhouette = true;
        }
        if (!nearSilhouette) ++a.farFromSilhouette;
        continue;
      }
      if (!l) continue;
      ++a.bothHit;
      a.worstT = std::max(a.worstT, std::abs(hl.t - he.t));
      a.meanNormalDot += glm::dot(hl.normal, he.normal);
    }
  if (a.bothHit) a.meanNormalDot /= a.bothHit;
  return a;
}

}  // namespace

TEST_CASE("lattice leaf: a placed capsule lattice matches the exact capsule") {
  // A line of length 10 lambda, lambda = 0.1, tilted and moved in the world.
  const LatticeObject capsule = capsuleObject(0.05, 1.0);
  const auto lht = rasterizeObject(capsule, 0.1, 2.0);
  const Mat4d place = glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.5)) *
                      glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 1, 0)));
  const auto lattice = makeLatticeLeaf<double>(lht, place, 3);
  const auto exact = makeCapsule<double>(0.05, 1.0, place, 3);
  const double cell = 0.05;  // lambda / f_lat
  for (const Vec3d& dir : {Vec3d(0, 0, -1), Vec3d(1, 0.3, -0.2), Vec3d(-0.4, 1, 0.5)}) {
    INFO("direction " << dir.x << " " << dir.y << " " << dir.z);
    const Agreement a = compare(*lattice, *exact, dir, cell);
    REQUIRE(a.bothHit > 50);
    // Rounding entry and exit to the grid moves the ray by up to half a cell
    // at each end, so only rays within about a cell of the silhouette may flip
    // (for a line 2 cells thick that is a good share of them).
    CHECK(a.farFromSilhouette == 0);
    CHECK(a.disagree <= a.bothHit / 2);
    CHECK(a.worstT <= 1.5 * cell);
    CHECK(a.meanNormalDot > 0.9);
  }
}

TEST_CASE("lattice leaf: spans have the material, outward normals, and work in CSG") {
  const LatticeObject sphere = sphereObject(1.0);
  const auto lht = rasterizeObject(sphere, 2.0, 8.0);  // a 16^3 lattice around a unit sphere
  const auto lattice = makeLatticeLeaf<double>(lht, Mat4d(1.0), 7);
  const Ray<double> ray{Vec3d(0.05, 0.02, -5), Vec3d(0, 0, 1)};
  SpanList<double> spans;
  lattice->spans(ray, 0.0, 100.0, spans);
  REQUIRE(spans.size() == 1);
  CHECK(spans[0].enter.t == Approx(4.0).margin(0.2));
  CHECK(spans[0].leave.t == Approx(6.0).margin(0.2));
  CHECK(spans[0].enter.normal.z < -0.9);
  CHECK(spans[0].leave.normal.z > 0.9);
  CHECK(spans[0].enter.material == 7);
  // Lattice minus a half-space z > 0: the ray leaves where the plane cuts it.
  std::vector<PrimitivePtr<double>> parts;
  parts.push_back(makeLatticeLeaf<double>(lht, Mat4d(1.0), 7));
  const QuarticShape cut = halfSpace(Vec3d(0, 0, -1), 0.0);  // -z < 0, i.e. z > 0
  parts.push_back(makeQuarticLeaf<double>(cut.f, cut.bounds, Mat4d(1.0), 1));
  const auto difference = makeCsgNode<double>(CsgOp::Difference, std::move(parts));
  SpanList<double> cutSpans;
  difference->spans(ray, 0.0, 100.0, cutSpans);
  REQUIRE(cutSpans.size() == 1);
  CHECK(cutSpans[0].leave.t == Approx(5.0).margin(1e-9));
}

TEST_CASE("lattice leaf: lit points do not shadow themselves, shadows fall on the far side") {
  const LatticeObject sphere = sphereObject(1.0);
  const auto lht = rasterizeObject(sphere, 2.0, 8.0);
  const auto lattice = makeLatticeLeaf<double>(lht, Mat4d(1.0), 0);
  const Vec3d light(0, 0, -10);  // towards the camera side
  int lit = 0, acne = 0;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j) {
      const Ray<double> ray{Vec3d(i * 0.1, j * 0.1, -5), Vec3d(0, 0, 1)};
      Hit<double> hit;
      if (!lattice->firstHit(ray, 0.0, 100.0, hit)) continue;
      const Vec3d p = ray.at(hit.t);
      const Ray<double> shadow{p, light - p};
      ++lit;
      if (lattice->anyHit(shadow, 1e-6, 1.0)) ++acne;
    }
  REQUIRE(lit > 50);
  CHECK(acne == 0);
  // A point behind the sphere, seen from the light, is in its shadow.
  const Ray<double> blocked{Vec3d(0, 0, 3), light - Vec3d(0, 0, 3)};
  CHECK(lattice->anyHit(blocked, 1e-6, 1.0));
  // With lattice shadows off (thesis plate 3) nothing is blocked.
  const auto noShadows = makeLatticeLeaf<double>(lht, Mat4d(1.0), 0, false);
  CHECK_FALSE(noShadows->anyHit(blocked, 1e-6, 1.0));
}

TEST_CASE("lattice leaf: the float path agrees with double") {
  const LatticeObject capsule = capsuleObject(0.5, 4.0);
  const auto lht = rasterizeObject(capsule, 1.0, 1.0);
  const auto ld = makeLatticeLeaf<double>(lht, Mat4d(1.0), 0);
  const auto lf = makeLatticeLeaf<float>(lht, Mat4d(1.0), 0);
  int agree = 0, total = 0;
  for (int i = 0; i < 40; ++i) {
    const Vec3d o(-3.0, -0.8 + i * 0.04, 2.0 + 0.01 * i);
    Hit<double> hd;
    Hit<float> hf;
    const bool bd = ld->firstHit(Ray<double>{o, Vec3d(1, 0.01, 0.02)}, 0.0, 100.0, hd);
    const bool bf = lf->firstHit(Ray<float>{Vec3<float>(o), Vec3<float>(1, 0.01f, 0.02f)}, 0.0f, 100.0f, hf);
    ++total;
    if (bd == bf && (!bd || std::abs(hd.t - double(hf.t)) < 1e-3)) ++agree;
  }
  CHECK(agree >= total - 2);  // a ray exactly between two grid points may round differently
}

TEST_CASE("lattice leaf: the blended look-up agrees with the exact capsule at least as well as the thesis's") {
  // A line one cell thick (f_lat 1), as the plates' hairs are: rounding the
  // ray's ends decides hit or miss across most of its width.
  const LatticeObject capsule = capsuleObject(0.05, 1.0);
  const auto lht = rasterizeObject(capsule, 0.1, 1.0);
  const Mat4d place = glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.5)) *
                      glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 1, 0)));
  const auto thesis = makeLatticeLeaf<double>(lht, place, 3, true, nullptr, LatticeLookup::Thesis);
  const auto blend = makeLatticeLeaf<double>(lht, place, 3, true, nullptr, LatticeLookup::Blend);
  const auto exact = makeCapsule<double>(0.05, 1.0, place, 3);
  const double cell = 0.1;
  int thesisDisagree = 0, blendDisagree = 0;
  for (const Vec3d& dir : {Vec3d(0, 0, -1), Vec3d(1, 0.3, -0.2), Vec3d(-0.4, 1, 0.5)}) {
    INFO("direction " << dir.x << " " << dir.y << " " << dir.z);
    const Agreement t = compare(*thesis, *exact, dir, cell);
    const Agreement b = compare(*blend, *exact, dir, cell);
    INFO("disagreeing rays: thesis " << t.disagree << ", blend " << b.disagree << "; mean normal dot: thesis "
                                     << t.meanNormalDot << ", blend " << b.meanNormalDot);
    REQUIRE(b.bothHit > 50);
    CHECK(b.farFromSilhouette == 0);
    CHECK(b.worstT <= 1.5 * cell);
    CHECK(b.meanNormalDot >= t.meanNormalDot - 0.01);
    thesisDisagree += t.disagree;
    blendDisagree += b.disagree;
  }
  INFO("disagreeing rays over the three directions: thesis " << thesisDisagree << ", blend " << blendDisagree);
  CHECK(blendDisagree <= thesisDisagree);
}
