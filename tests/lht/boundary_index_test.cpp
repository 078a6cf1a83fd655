// The numbering of a lattice box's surface points (lht/grid/boundary_index.hpp):
// the pair space the compressed table and the look-up statistics index.
#include <catch2/catch.hpp>

#include "lht/grid/boundary_index.hpp"

using namespace lattice::lht;

TEST_CASE("boundary index: numbers the surface points in boundaryPoints() order, and nothing else") {
  for (const std::array<int, 3> cells : {std::array{1, 1, 1}, std::array{2, 3, 4}, std::array{5, 1, 7},
                                         std::array{6, 3, 19}, std::array{1, 9, 2}, std::array{4, 4, 1}}) {
    INFO(cells[0] << " x " << cells[1] << " x " << cells[2]);
    const LatticeBox box(cells, 1.0, 1.0, lattice::Vec3d(0.0));
    const BoundaryIndex index(cells);
    const std::vector<LatticePoint> points = box.boundaryPoints();
    REQUIRE(index.count() == points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      CHECK(index.indexOf(points[i]) == i);
      CHECK(index.pointAt(i) == points[i]);
    }
    // Inside points and points beyond the box have no number.
    std::size_t numbered = 0;
    for (int x = 0; x <= cells[0] + 1; ++x)
      for (int y = 0; y <= cells[1] + 1; ++y)
        for (int z = 0; z <= cells[2] + 1; ++z) {
          const LatticePoint p{std::uint8_t(x), std::uint8_t(y), std::uint8_t(z)};
          const bool inBox = x <= cells[0] && y <= cells[1] && z <= cells[2];
          if (index.indexOf(p) != BoundaryIndex::kNotOnBoundary) ++numbered;
          CHECK((index.indexOf(p) != BoundaryIndex::kNotOnBoundary) == (inBox && box.onBoundary(p)));
        }
    CHECK(numbered == points.size());
  }
}
