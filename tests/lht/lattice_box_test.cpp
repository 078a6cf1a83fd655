#include <catch2/catch.hpp>

#include <set>
#include <tuple>

#include "lht/grid/lattice_box.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::lht;

TEST_CASE("lattice box: padded by lambda/2 and divided into cells of lambda/f_lat") {
  const Bounds<double> unitSphere{Vec3d(-0.5), Vec3d(0.5)};
  CHECK(LatticeBox(unitSphere, 1.0, 1.0).cells() == std::array<int, 3>{2, 2, 2});
  CHECK(LatticeBox(unitSphere, 1.0, 3.0).cells() == std::array<int, 3>{6, 6, 6});
  const Bounds<double> line{Vec3d(-0.5, -0.5, -0.5), Vec3d(0.5, 0.5, 10.5)};
  const LatticeBox box(line, 1.0, 2.0);
  CHECK(box.cells() == std::array<int, 3>{4, 4, 24});
  // The object's low corner sits half a lambda (one cell at f_lat 2) inside.
  const Vec3d lo = transformPoint(box.objectToLattice(), line.lo);
  CHECK(lo.x == Approx(1.0));
  CHECK(lo.z == Approx(1.0));
  const Vec3d back = transformPoint(box.latticeToObject(), Vec3d(4, 4, 24));
  CHECK(back.z == Approx(11.0));
}

TEST_CASE("lattice box: a non-integral extent is rounded up and the object centred") {
  const LatticeBox box({Vec3d(0.0), Vec3d(1.2, 1.0, 1.0)}, 1.0, 1.0);
  CHECK(box.cells()[0] == 3);  // 2.2 cells -> 3
  const Vec3d lo = transformPoint(box.objectToLattice(), Vec3d(0.0));
  CHECK(lo.x == Approx(0.9));
}

TEST_CASE("lattice box: coordinates beyond one byte and bad spacings are refused") {
  CHECK_THROWS_AS(LatticeBox({Vec3d(0.0), Vec3d(300.0, 1.0, 1.0)}, 1.0, 1.0), Error);
  CHECK_THROWS_AS(LatticeBox({Vec3d(0.0), Vec3d(1.0)}, 0.0, 1.0), Error);
  CHECK_THROWS_AS(LatticeBox({Vec3d(0.0), Vec3d(1.0)}, 1.0, 0.5), Error);
  CHECK_THROWS_AS(LatticeBox(Bounds<double>::infinite(), 1.0, 1.0), Error);
  CHECK_THROWS_AS(LatticeBox(Bounds<double>{}, 1.0, 1.0), Error);
  // 254 lambda of object + 1 of padding = 255 cells: the largest allowed.
  CHECK(LatticeBox({Vec3d(0.0), Vec3d(254.0, 1.0, 1.0)}, 1.0, 1.0).cells()[0] == 255);
}

TEST_CASE("lattice box: boundary points are the box surface, each once") {
  const LatticeBox box({Vec3d(0.0), Vec3d(2.0, 1.0, 3.0)}, 1.0, 1.0);  // 3 x 2 x 4 cells
  const auto points = box.boundaryPoints();
  std::set<std::tuple<int, int, int>> unique;
  for (const LatticePoint& p : points) {
    unique.emplace(p.x, p.y, p.z);
    CHECK(box.onBoundary(p));
  }
  CHECK(unique.size() == points.size());
  CHECK(points.size() == std::size_t(4 * 3 * 5 - 2 * 1 * 3));  // all grid points minus the interior
}

TEST_CASE("lattice box: summing face-pair multiplicities gives eq. 1.3") {
  for (const Vec3d& extent : {Vec3d(1.0), Vec3d(3.0, 1.0, 3.0), Vec3d(1.0, 1.0, 11.0), Vec3d(2.5, 4.0, 0.2)}) {
    const LatticeBox box({Vec3d(0.0), extent}, 1.0, 1.0);
    const auto points = box.boundaryPoints();
    std::uint64_t sum = 0;
    for (const LatticePoint& a : points)
      for (const LatticePoint& b : points) sum += std::uint64_t(LatticeBox::pairMultiplicity(box.facesOf(a), box.facesOf(b)));
    CHECK(sum == box.pairCountEq13());
  }
  // Figure 2: a 4 x 2 x 4 lattice has 9950 pairs (thesis sec. 2.2).
  CHECK(LatticeBox({Vec3d(0.0), Vec3d(3.0, 1.0, 3.0)}, 1.0, 1.0).pairCountEq13() == 9950);
  // A corner point lies on three faces; with a point of one other face it
  // pairs three times, with itself 3*3-3 = 6 times.
  CHECK(LatticeBox::pairMultiplicity(0b010101, 0b100000) == 3);
  CHECK(LatticeBox::pairMultiplicity(0b010101, 0b010101) == 6);
  CHECK(LatticeBox::pairMultiplicity(0b000001, 0b000001) == 0);
}
