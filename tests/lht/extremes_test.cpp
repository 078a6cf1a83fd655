// Lattices at the extremes, for each arithmetic (float, double, Fixed32):
// boxes of 255 cells and of 1 cell per axis, normals at the limits of the
// LHT's signed-byte quantization, s at exactly 0 and 1, instances scaled by
// 1e-4 and 1e4, and the transforms a lattice instance may not have. The
// lookup itself is integer in every arithmetic, so the reference is the
// double leaf on the same table (they may differ only where a ray's box
// entry or exit lies on a rounding boundary of the grid) and, for the
// lattice's own accuracy, the exact object. Figures: docs/stability.md.
#include <catch2/catch.hpp>

#include <array>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "lht/leaf/lattice_leaf.hpp"
#include "lht/raster/lattice_object.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "lht/table/hash_table.hpp"
#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "tests/lht/raster_support.hpp"
#include "tests/render/extremes_support.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::lht;
using namespace lattice::testing;

namespace {

// A hit through the thesis's 14-byte entry and back (the other forms'
// bounds are tests/lht/entry_codec_test.cpp's).
LhtHit thesisRoundTrip(const RasterHit& hit) {
  std::array<std::uint8_t, 16> entry{};
  encodeEntry(hit, LhtPrecision::Thesis, entry.data());
  return decodeEntry(entry.data(), LhtPrecision::Thesis);
}

// A rotation and a translation, scaled by k.
Mat4d placement(double k) {
  return glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.5) * k) *
         glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 2, 3))) * glm::scale(Mat4d(1.0), Vec3d(k));
}

struct LeafAgreement {
  int rays = 0, hits = 0;
  int ties = 0;           // box entry or exit within tieCells of a rounding boundary: either answer is right
  int disagreements = 0;  // hit/miss or lookup differs from double, away from ties
  double worstCells = 0;  // |t - t_double| in cells, where both hit and no tie
  double worstNormalAngle = 0;
  double worstUnitError = 0;  // | |n| - 1 |
};

// How close the line's box entry and exit (lattice coordinates, in double)
// come to a rounding boundary of the grid (a half-integer coordinate).
double distanceToRoundingBoundary(const Ray<double>& latticeRay, const std::array<int, 3>& cells) {
  const Bounds<double> box{Vec3d(0.0), Vec3d(cells[0], cells[1], cells[2])};
  double t0 = 0, t1 = 0;
  if (!box.clip(latticeRay, -INFINITY, INFINITY, t0, t1)) return INFINITY;
  double nearest = INFINITY;
  for (const Vec3d& p : {latticeRay.at(t0), latticeRay.at(t1)})
    for (int a = 0; a < 3; ++a) nearest = std::min(nearest, std::abs(p[a] - std::floor(p[a]) - 0.5));
  return nearest;
}

// The T leaf against the double leaf of the same table and placement, ray by
// ray (world rays given by two world points each).
template <typename T>
LeafAgreement compareWithDoubleLeaf(const std::shared_ptr<const LhtFile>& lht, const Mat4d& place,
                                    const std::vector<std::pair<Vec3d, Vec3d>>& rays, double tieCells) {
  const auto leaf = makeLatticeLeaf<T>(lht, place, 0);
  const auto reference = makeLatticeLeaf<double>(lht, place, 0);
  const Mat4d worldToLattice = glm::inverse(place * lht->box.latticeToObject());
  LeafAgreement a;
  for (const auto& [from, to] : rays) {
    const Ray<double> rd{from, to - from};
    const Ray<T> rt{Vec3<T>(from), Vec3<T>(to - from)};
    const Ray<double> inLattice = rd.transformed(worldToLattice);
    ++a.rays;
    if (distanceToRoundingBoundary(inLattice, lht->box.cells()) < tieCells) {
      ++a.ties;
      continue;
    }
    Hit<double> hd;
    Hit<T> ht;
    const bool bd = reference->firstHit(rd, 0.0, INFINITY, hd);
    const bool bt = leaf->firstHit(rt, T(0), std::numeric_limits<T>::infinity(), ht);
    if (bd != bt) {
      ++a.disagreements;
      continue;
    }
    if (!bd) continue;
    ++a.hits;
    const double cellT = 1.0 / glm::length(inLattice.direction);  // t per cell along this ray
    const double cells = std::abs(static_cast<double>(ht.t) - hd.t) / cellT;
    if (cells > 1e-2) ++a.disagreements;  // another lookup: another entry
    a.worstCells = std::max(a.worstCells, cells);
    const Vec3d n = toDouble(ht.normal);
    a.worstNormalAngle = std::max(a.worstNormalAngle, angleBetween(n, hd.normal));
    a.worstUnitError = std::max(a.worstUnitError, std::abs(glm::length(n) - 1.0));
  }
  return a;
}

// Stated bounds of the comparison with the double leaf: rays within
// tieCells of a rounding boundary may round either way; away from them the
// lookups agree and t and the normal differ only by T's rounding.
template <typename T>
double tieCells() {
  return bound<T>(1e-3, 0.0, 1e-5);
}

template <typename T>
void checkAgreement(const std::string& what, const LeafAgreement& a, int minimumHits) {
  INFO(what);
  // Float's box entry moves along the ray by its rounding of the face's
  // coordinate divided by the sine of the angle between ray and face: for
  // rays 640 cells long skimming the long faces of a 255-cell box that is
  // up to ~1e-2 cells (measured 8.9e-3).
  const double cellBound = bound<T>(2e-2, 1e-9, 1e-4);
  // Q31.32 rounds the normal matrix's entries (1 / the world size of a
  // cell) to 2^-32: at 1e4 scale they are ~4e-4, so normals keep ~21 bits.
  const double angleBound = bound<T>(1e-5, 1e-12, 1e-5);
  const double unitBound = bound<T>(1e-6, 1e-12, 1e-7);
  reportMeasure(what + ": rays within a tie of a rounding boundary", a.ties, a.rays / 100.0);
  reportMeasure(what + ": t difference from double (cells)", a.worstCells, cellBound);
  reportMeasure(what + ": normal angle from double (rad)", a.worstNormalAngle, angleBound);
  reportMeasure(what + ": | |n| - 1 |", a.worstUnitError, unitBound);
  CHECK(a.hits >= minimumHits);
  CHECK(a.ties <= a.rays / 100);
  CHECK(a.disagreements == 0);
  CHECK(a.worstCells <= cellBound);
  CHECK(a.worstNormalAngle <= angleBound);
  CHECK(a.worstUnitError <= unitBound);
}

// `count` random lines through a lattice's box (two random points on its
// surface, in lattice coordinates), as world point pairs from outside it.
std::vector<std::pair<Vec3d, Vec3d>> raysThroughBox(const LhtFile& lht, const Mat4d& place, int count) {
  const auto& c = lht.box.cells();
  const Mat4d toWorld = place * lht.box.latticeToObject();
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto onSurface = [&] {
    Vec3d p(u(rng) * c[0], u(rng) * c[1], u(rng) * c[2]);
    const int axis = static_cast<int>(u(rng) * 3) % 3;
    p[axis] = u(rng) < 0.5 ? 0.0 : c[axis];
    return p;
  };
  std::vector<std::pair<Vec3d, Vec3d>> rays;
  while (static_cast<int>(rays.size()) < count) {
    const Vec3d a = onSurface(), b = onSurface();
    if (glm::length(b - a) < 0.5) continue;
    // Start a box length outside, so the ray enters the box.
    const Vec3d from = a - (b - a) * 1.5;
    rays.emplace_back(transformPoint(toWorld, from), transformPoint(toWorld, b));
  }
  return rays;
}

}  // namespace

TEMPLATE_TEST_CASE("lattice extremes: a lattice of 255 cells per axis", "[extremes]", float, double, Fixed32) {
  using T = TestType;
  // A box of 1 x 1 x 255 cells (the most a byte holds along z) around a
  // capsule along its axis, placed at 1/100 scale: the lookup keys reach
  // coordinate 255 and the leaf's t spans 255 cells.
  const LatticeObject capsule = capsuleObject(0.3, 254.0);
  const LatticeBox box({1, 1, 255}, 1.0, 1.0, Vec3d(-0.5, -0.5, -0.5));
  const auto lht = rasterizeInBox(capsule, box);
  REQUIRE(lht->entryCount() > 0);
  const Mat4d place = placement(0.01);
  std::vector<std::pair<Vec3d, Vec3d>> rays = raysThroughBox(*lht, place, 3000);
  // And the far end: from the corner (0, 0, 250) to (1, 1, 255), and back.
  const Mat4d toWorld = place * lht->box.latticeToObject();
  for (const auto& [a, b] : {std::pair{Vec3d(0, 0, 250), Vec3d(1, 1, 255)}, std::pair{Vec3d(1, 1, 255), Vec3d(0, 0, 250)},
                             std::pair{Vec3d(0, 1, 253), Vec3d(1, 0, 255)}})
    rays.emplace_back(transformPoint(toWorld, a - (b - a)), transformPoint(toWorld, b));
  checkAgreement<T>(fmt::format("{} lattice 1x1x255", arithmeticName<T>()),
                    compareWithDoubleLeaf<T>(lht, place, rays, tieCells<T>()), 200);
  // The far-end rays hit in every arithmetic.
  const auto leaf = makeLatticeLeaf<T>(lht, place, 0);
  for (std::size_t i = rays.size() - 3; i < rays.size(); ++i) {
    Hit<T> hit;
    CHECK(leaf->firstHit(Ray<T>{Vec3<T>(rays[i].first), Vec3<T>(rays[i].second - rays[i].first)}, T(0),
                         std::numeric_limits<T>::infinity(), hit));
  }
}

TEST_CASE("lattice extremes: a lattice box holds at most 255 cells per axis") {
  // A capsule of radius lambda/2 and length L needs L + 2 cells along its
  // axis (f_lat 1): 253 gives exactly 255, 254 one too many - refused
  // saying how to fix it.
  const LatticeBox largest(capsuleObject(0.5, 253.0).bounds, 1.0, 1.0);
  CHECK(largest.cells()[2] == 255);
  CHECK(largest.cells()[0] == 2);
  REQUIRE_THROWS_WITH(LatticeBox(capsuleObject(0.5, 254.0).bounds, 1.0, 1.0),
                      Catch::Contains("256 cells along z") && Catch::Contains("at most 255") &&
                          Catch::Contains("larger spacing lambda"));
  CHECK_NOTHROW(LatticeBox({1, 1, 1}, 1.0, 1.0, Vec3d(0.0)));
  CHECK_THROWS_WITH(LatticeBox({1, 0, 1}, 1.0, 1.0, Vec3d(0.0)), Catch::Contains("outside 1..255"));
  CHECK_THROWS_WITH(LatticeBox({1, 1, 256}, 1.0, 1.0, Vec3d(0.0)), Catch::Contains("outside 1..255"));
}

TEMPLATE_TEST_CASE("lattice extremes: a lattice of one cell", "[extremes]", float, double, Fixed32) {
  using T = TestType;
  // One cell: the grid points are the 8 corners, and the only segments that
  // are traced are the 4 body diagonals (every other pair shares a face).
  // A sphere of radius 0.4 cells at the centre meets all of them.
  const LatticeObject ball = sphereObject(0.4);
  const auto lht = rasterizeInBox(ball, LatticeBox({1, 1, 1}, 1.0, 1.0, Vec3d(-0.5)));
  REQUIRE(lht->entryCount() == 8);  // 4 diagonals, both ways
  const Mat4d place = placement(1.0);
  checkAgreement<T>(fmt::format("{} lattice 1x1x1", arithmeticName<T>()),
                    compareWithDoubleLeaf<T>(lht, place, raysThroughBox(*lht, place, 3000), tieCells<T>()), 50);
  // A body diagonal hits, at the sphere (0.5 - 0.4 / sqrt(3) of the way in,
  // to within the quantization of s, 1/510) with the normal facing back along it.
  const auto leaf = makeLatticeLeaf<T>(lht, place, 0);
  const Mat4d toWorld = place * lht->box.latticeToObject();
  const Vec3d from = transformPoint(toWorld, Vec3d(-1.0)), to = transformPoint(toWorld, Vec3d(1.0));
  Hit<T> hit;
  REQUIRE(leaf->firstHit(Ray<T>{Vec3<T>(from), Vec3<T>(to - from)}, T(0), std::numeric_limits<T>::infinity(), hit));
  const double sExact = 0.5 - 0.4 / std::sqrt(3.0);  // of the diagonal, which is the middle half of the ray
  CHECK(std::abs(static_cast<double>(hit.t) - (0.5 + 0.5 * sExact)) <= 0.5 / 255 / 2 + 1e-6);
  CHECK(glm::dot(toDouble(hit.normal), glm::normalize(to - from)) < -0.99);
  // A ray along an edge of the cell rounds to two corners on a common face: no entry, a miss.
  const Vec3d e0 = transformPoint(toWorld, Vec3d(0.1, 0.1, -1.0)), e1 = transformPoint(toWorld, Vec3d(0.1, 0.1, 2.0));
  CHECK_FALSE(leaf->firstHit(Ray<T>{Vec3<T>(e0), Vec3<T>(e1 - e0)}, T(0), std::numeric_limits<T>::infinity(), hit));
}

namespace {

// A hand-made 4 x 4 x 4 table: for each (y, z) in 1..3 the pair
// (0, y, z) -> (4, y, z) and back, with chosen s and normals. Rays along x
// through (y, z) look them up.
struct HandMadeEntry {
  int y, z;
  double sIn, sOut;  // entering hit, and the leaving one measured from the far face
  Vec3d normalIn, normalOut;
};

std::shared_ptr<const LhtFile> handMadeTable(const std::vector<HandMadeEntry>& entries) {
  auto file = std::make_shared<LhtFile>();
  file->box = LatticeBox({4, 4, 4}, 1.0, 1.0, Vec3d(0.0));
  std::vector<RasterHit> hits;
  for (const HandMadeEntry& e : entries) {
    const LatticePoint near{0, static_cast<std::uint8_t>(e.y), static_cast<std::uint8_t>(e.z)};
    const LatticePoint far{4, static_cast<std::uint8_t>(e.y), static_cast<std::uint8_t>(e.z)};
    hits.push_back({near, far, e.sIn, e.normalIn});
    hits.push_back({far, near, e.sOut, e.normalOut});
  }
  file->table = LatticeHashTable(hits);
  return file;
}

// The world ray along lattice x through (y, z), starting 2 cells before the
// box, with t = 1 per cell: the box spans t in [2, 6].
Ray<double> alongX(const Mat4d& latticeToWorld, int y, int z) {
  const Vec3d from = transformPoint(latticeToWorld, Vec3d(-2, y, z));
  return {from, transformPoint(latticeToWorld, Vec3d(-1, y, z)) - from};
}

}  // namespace

TEMPLATE_TEST_CASE("lattice extremes: s at exactly 0 and 1 puts hits on the box faces", "[extremes]", float, double,
                   Fixed32) {
  using T = TestType;
  // s = 0 enters where the ray enters the box; s = 1 where it leaves it. The
  // leaving hit is measured from the far face, so sOut = 0 leaves at the
  // exit face and sOut = 1 at the entry face. Placed at scales 1e-4, 1 and
  // 1e4; t is 2 and 6 at the faces (in units of the scaled cell).
  const Vec3d x(1, 0, 0);
  const auto lht = handMadeTable({
      {1, 1, 0.0, 0.0, -x, x},  // the whole chord: [entry face, exit face]
      {2, 2, 1.0, 0.0, -x, x},  // enters at the exit face
      {3, 3, 0.0, 1.0, -x, x},  // leaves at the entry face: a span of no length at t = 2
  });
  // t is 2 and 6 exactly in double; T's rounding of the ray and of the
  // world -> lattice matrix moves the faces: float by its relative
  // precision, Q31.32 by about 2^-33 times the world distance of the ray's
  // origin, in cells (at 1e4: 2e4 world units, 5e-6 cells).
  const double tolerance = bound<T>(4e-6, 1e-12, 2e-5);
  double worst = 0;
  for (double k : {1e-4, 1.0, 1e4}) {
    INFO("scale " << k);
    const Mat4d latticeToWorld = placement(k) * lht->box.latticeToObject();
    const auto leaf = makeLatticeLeaf<T>(lht, placement(k), 0);
    const auto spansOf = [&](int y, int z) {
      const Ray<double> r = alongX(latticeToWorld, y, z);
      SpanList<T> out;
      leaf->spans(Ray<T>{Vec3<T>(r.origin), Vec3<T>(r.direction)}, -std::numeric_limits<T>::infinity(),
                  std::numeric_limits<T>::infinity(), out);
      return out;
    };
    const auto near = [&](T t, double expected) {
      worst = std::max(worst, std::abs(static_cast<double>(t) - expected));
      return std::abs(static_cast<double>(t) - expected) <= tolerance;
    };
    const SpanList<T> whole = spansOf(1, 1);
    REQUIRE(whole.size() == 1);
    CHECK(near(whole[0].enter.t, 2.0));
    CHECK(near(whole[0].leave.t, 6.0));
    const SpanList<T> atExit = spansOf(2, 2);
    REQUIRE(atExit.size() == 1);
    CHECK(near(atExit[0].enter.t, 6.0));
    CHECK(near(atExit[0].leave.t, 6.0));
    const SpanList<T> atEntry = spansOf(3, 3);
    REQUIRE(atEntry.size() == 1);
    CHECK(near(atEntry[0].enter.t, 2.0));
    CHECK(near(atEntry[0].leave.t, 2.0));  // clamped up to the entry: never a span that ends before it starts
    for (const SpanList<T>* list : {&whole, &atExit, &atEntry}) {
      CHECK((*list)[0].enter.t <= (*list)[0].leave.t);
      // Normals: -x in, +x out, in the world.
      const Vec3d worldX = glm::normalize(glm::dmat3(placement(k)) * x);
      CHECK(angleBetween(toDouble((*list)[0].enter.normal), -worldX) < 1e-5);
      CHECK(angleBetween(toDouble((*list)[0].leave.normal), worldX) < 1e-5);
    }
  }
  reportMeasure(fmt::format("{} lattice s = 0 and 1: t off the box faces (cells)", arithmeticName<T>()), worst,
                tolerance);
}

TEST_CASE("lattice extremes: normals quantized to signed bytes decode to unit vectors within 0.4 degrees") {
  // Each component is stored as round(127 n), so it is off by at most
  // 1/254; renormalized, the direction is off by at most
  // asin(sqrt(3) / 254 / (1 - sqrt(3) / 254)) = 0.0069 rad (0.39 degrees).
  const double statedBound = 0.0069;
  const auto decoded = [](const Vec3d& n) {
    RasterHit hit;
    hit.in = {0, 1, 1};
    hit.out = {4, 1, 1};
    hit.normal = n;
    return thesisRoundTrip(hit).normal;
  };
  // Along the axes and the diagonals the stored bytes are exact or equal,
  // so the decoded direction is exact.
  for (int a = 0; a < 3; ++a)
    for (double sign : {-1.0, 1.0}) {
      Vec3d n(0.0);
      n[a] = sign;
      CHECK(decoded(n) == n);
    }
  for (const Vec3d& d : {Vec3d(1, 1, 0), Vec3d(1, -1, 0), Vec3d(0, 1, 1), Vec3d(1, 1, 1), Vec3d(-1, 1, -1)}) {
    const Vec3d n = glm::normalize(d);
    CHECK(angleBetween(decoded(n), n) < 1e-15);
    CHECK(std::abs(glm::length(decoded(n)) - 1.0) < 1e-15);
  }
  // Directions at the quantization limits: components just below and above
  // half a step (0.5 / 127), near-axis and random ones.
  std::vector<Vec3d> hard;
  for (double e : {0.49 / 127, 0.51 / 127, 1.49 / 127, 1.51 / 127, 1e-9})
    hard.push_back(glm::normalize(Vec3d(1, e, -e)));
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (int i = 0; i < 100000; ++i) hard.push_back(glm::normalize(Vec3d(g(rng), g(rng), g(rng))));
  double worst = 0, worstUnit = 0;
  for (const Vec3d& n : hard) {
    worst = std::max(worst, angleBetween(decoded(n), n));
    worstUnit = std::max(worstUnit, std::abs(glm::length(decoded(n)) - 1.0));
  }
  reportMeasure("LHT normal quantization: worst angle (rad) over 100005 directions", worst, statedBound);
  CHECK(worst <= statedBound);
  CHECK(worstUnit < 1e-15);
}

TEMPLATE_TEST_CASE("lattice extremes: normals at the quantization limits reach the world unit and in direction",
                   "[extremes]", float, double, Fixed32) {
  using T = TestType;
  // Stored normals along axes, diagonals and at the rounding limits, looked
  // up through a rotated lattice scaled by 1e-4, 1 and 1e4: the world normal
  // must be unit and the transform of the decoded (double) normal, to T's
  // rounding. (Fixed point decodes the bytes itself, in integers.)
  const std::vector<Vec3d> normals = {
      Vec3d(-1, 0, 0), glm::normalize(Vec3d(-1, 1, 0)), glm::normalize(Vec3d(-1, -1, 1)),
      glm::normalize(Vec3d(-1, 0.51 / 127, 0)), glm::normalize(Vec3d(-1, 0.49 / 127, -1.51 / 127)),
      Vec3d(0, 0, 1),  // at right angles to the ray
      glm::normalize(Vec3d(-1, 1e-9, 1e-9)),
  };
  std::vector<HandMadeEntry> entries;
  for (std::size_t i = 0; i < normals.size(); ++i)
    entries.push_back({1 + int(i) % 3, 1 + int(i) / 3, 0.25, 0.25, normals[i], -normals[i]});
  const auto lht = handMadeTable(entries);
  const double unitBound = bound<T>(1e-6, 1e-14, 1e-7);
  const double angleBound = bound<T>(1e-6, 1e-14, 1e-5);
  double worstUnit = 0, worstAngle = 0;
  for (double k : {1e-4, 1.0, 1e4}) {
    const Mat4d latticeToWorld = placement(k) * lht->box.latticeToObject();
    const glm::dmat3 normalToWorld = glm::transpose(glm::inverse(glm::dmat3(latticeToWorld)));
    const auto leaf = makeLatticeLeaf<T>(lht, placement(k), 0);
    for (const HandMadeEntry& e : entries) {
      const Ray<double> r = alongX(latticeToWorld, e.y, e.z);
      Hit<T> hit;
      REQUIRE(leaf->firstHit(Ray<T>{Vec3<T>(r.origin), Vec3<T>(r.direction)}, T(0), std::numeric_limits<T>::infinity(),
                             hit));
      RasterHit stored;
      stored.normal = e.normalIn;
      const Vec3d expected = glm::normalize(normalToWorld * thesisRoundTrip(stored).normal);
      const Vec3d n = toDouble(hit.normal);
      worstUnit = std::max(worstUnit, std::abs(glm::length(n) - 1.0));
      worstAngle = std::max(worstAngle, angleBetween(n, expected));
    }
  }
  const std::string what = fmt::format("{} lattice normals at the quantization limits", arithmeticName<T>());
  reportMeasure(what + ": | |n| - 1 |", worstUnit, unitBound);
  reportMeasure(what + ": angle from the decoded normal (rad)", worstAngle, angleBound);
  CHECK(worstUnit <= unitBound);
  CHECK(worstAngle <= angleBound);
}

namespace {

struct ExactAgreement {
  int rays = 0, bothHit = 0, farFromSilhouette = 0;
  double worstCells = 0;  // |t - t_exact| in cells
  double worstNormalAngle = 0;
};

// The T lattice leaf of a sphere against the exact sphere (double), both
// placed by `place`: the lattice's own bound (docs/lattices.md).
template <typename T>
ExactAgreement sphereLatticeAgainstExact(const std::shared_ptr<const LhtFile>& lht, const Mat4d& place, double k) {
  const auto leaf = makeLatticeLeaf<T>(lht, place, 0);
  const QuarticShape exactShape = sphere(1.0);
  const auto exact = makeQuarticLeaf<double>(exactShape.f, exactShape.bounds, place, 0);
  const double cell = lht->box.cellSize() * k;  // world units
  ExactAgreement a;
  const Vec3d eye = Vec3d(0.5, 1.5, -4) * k;
  for (int i = 0; i < 48; ++i)
    for (int j = 0; j < 48; ++j) {
      const Vec3d d = Vec3d(0.3 + (i - 23.5) / 20.0, -0.2 + (j - 23.5) / 20.0, 0.5) * k - eye;
      Hit<T> hl;
      Hit<double> he;
      const bool l = leaf->firstHit(Ray<T>{Vec3<T>(eye), Vec3<T>(d)}, T(0), std::numeric_limits<T>::infinity(), hl);
      const bool e = exact->firstHit(Ray<double>{eye, d}, 0.0, INFINITY, he);
      ++a.rays;
      const double cellT = cell / glm::length(d);
      if (l != e) {
        // Rounding to the grid moves a ray by up to half a cell at each end:
        // only rays within a cell of the silhouette may flip.
        bool nearSilhouette = false;
        for (double sx : {-1.0, 1.0})
          for (double sy : {-1.0, 1.0}) {
            Hit<double> shifted;
            const Vec3d offset = glm::normalize(glm::cross(d, Vec3d(sx, sy, 0.3))) * cell;
            nearSilhouette = nearSilhouette || exact->firstHit(Ray<double>{eye + offset, d}, 0.0, INFINITY, shifted) != e;
          }
        if (!nearSilhouette) ++a.farFromSilhouette;
        continue;
      }
      if (!l) continue;
      ++a.bothHit;
      a.worstCells = std::max(a.worstCells, std::abs(static_cast<double>(hl.t) - he.t) / cellT);
      a.worstNormalAngle = std::max(a.worstNormalAngle, angleBetween(toDouble(hl.normal), he.normal));
    }
  return a;
}

}  // namespace

TEMPLATE_TEST_CASE("lattice extremes: instances scaled by 1e-4 and 1e4 keep the lattice's accuracy", "[extremes]",
                   float, double, Fixed32) {
  using T = TestType;
  // A sphere lattice of 16^3 cells placed at 1e-4, 1 and 1e4: against the
  // exact sphere, within the lattice's own bound (1.5 cells in t, normals of
  // a 4-cell radius sphere seen through half-cell rounding); against the
  // double leaf, the same lookups. At 1e-4 a cell is 2.5e-5 world units.
  const auto lht = rasterizeObject(sphereObject(1.0), 2.0, 8.0);
  for (double k : {1e-4, 1.0, 1e4}) {
    const std::string what = fmt::format("{} sphere lattice scaled by {:g}", arithmeticName<T>(), k);
    INFO(what);
    const ExactAgreement a = sphereLatticeAgainstExact<T>(lht, placement(k), k);
    reportMeasure(what + ": |t - t_exact| (cells)", a.worstCells, 1.5);
    reportMeasure(what + ": normal angle from exact (rad)", a.worstNormalAngle, 0.4);
    REQUIRE(a.bothHit > 1000);
    CHECK(a.farFromSilhouette == 0);
    CHECK(a.worstCells <= 1.5);
    CHECK(a.worstNormalAngle <= 0.4);
    checkAgreement<T>(what, compareWithDoubleLeaf<T>(lht, placement(k), raysThroughBox(*lht, placement(k), 2000),
                                                     tieCells<T>()),
                      200);
  }
}

TEMPLATE_TEST_CASE("lattice extremes: fixed point refuses cells below 1e-6 world units", "[extremes]", float, double,
                   Fixed32) {
  using T = TestType;
  // A cell of 0.25 object units, scaled to 1.05e-6 and 0.95e-6 world units.
  const auto lht = rasterizeObject(sphereObject(1.0), 2.0, 8.0);
  const double above = 1.05e-6 / 0.25, below = 0.95e-6 / 0.25;
  const ExactAgreement a = sphereLatticeAgainstExact<T>(lht, placement(above), above);
  reportMeasure(fmt::format("{} sphere lattice, cells of 1.05e-6: |t - t_exact| (cells)", arithmeticName<T>()),
                a.worstCells, 1.5);
  CHECK(a.farFromSilhouette == 0);
  CHECK(a.worstCells <= 1.5);
  if constexpr (kIsIeee<T>) {
    CHECK_NOTHROW(makeLatticeLeaf<T>(lht, placement(below), 0));
  } else {
    CHECK_THROWS_WITH(makeLatticeLeaf<T>(lht, placement(below), 0),
                      Catch::Contains("9.5e-07 world units") && Catch::Contains("--arith double"));
  }
}

namespace {

const char* kLatticeScene = R"([[lattices]]
name = "bead"
spacing = 1.0
object = { type = "sphere", radius = 0.5 }
[[objects]]
type = "lattice"
lattice = "bead"
)";

}  // namespace

TEST_CASE("lattice extremes: nearly singular lattice instance transforms are refused at load") {
  const auto load = [](const std::string& keys) {
    return parseSceneWithLattices(std::string(kLatticeScene) + keys, "bead.toml").scene;
  };
  // The instance's keys are on line 8.
  REQUIRE_THROWS_WITH(load("scale = [1, 1, 1e-13]\n"),
                      Catch::StartsWith("bead.toml:8:") && Catch::Contains("nearly singular"));
  REQUIRE_THROWS_WITH(load("scale = [1, 1, 0.99e-6]\n"),
                      Catch::StartsWith("bead.toml:8:") && Catch::Contains("condition number"));
  CHECK_NOTHROW(load("scale = [1, 1, 1.01e-6]\n"));
  // Two nearly parallel axes (condition number cot(theta / 2) = 1e6 at theta = 2e-6).
  const auto shear = [](double theta) {
    return fmt::format("matrix = [[1, {:.17g}, 0, 0], [0, {:.17g}, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n",
                       std::cos(theta), std::sin(theta));
  };
  REQUIRE_THROWS_WITH(load(shear(1.98e-6)), Catch::StartsWith("bead.toml:8:") && Catch::Contains("nearly singular"));
  CHECK_NOTHROW(load(shear(2.02e-6)));
  // Between float's limit (1e4) and the file's (1e6): loads, and --arith
  // float refuses it when the scene is built, naming the instance.
  const SceneDesc squashed = load("scale = [1, 1, 1e-5]\n");
  RenderSettings settings;
  settings.width = settings.height = 8;
  REQUIRE_THROWS_WITH(Renderer<float>(squashed, settings),
                      Catch::StartsWith("bead.toml:5:") && Catch::Contains("--arith float") &&
                          Catch::Contains("use --arith double"));
}
