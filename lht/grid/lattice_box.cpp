#include "lht/grid/lattice_box.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>

#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

void checkSpacing(double lambda, double oversample) {
  if (!(lambda > 0.0) || !std::isfinite(lambda))
    throw Error(ErrorKind::Input, fmt::format("lattice spacing lambda must be a positive number, got {}; "
                                              "set it to the object's thickness",
                                              lambda));
  if (!(oversample >= 1.0) || !std::isfinite(oversample) || oversample > 255.0)
    throw Error(ErrorKind::Input,
                fmt::format("lattice oversampling f_lat must be between 1 and 255, got {}", oversample));
}

}  // namespace

LatticeBox::LatticeBox(const Bounds<double>& objectBounds, double lambda, double oversample)
    : lambda_(lambda), oversample_(oversample) {
  checkSpacing(lambda, oversample);
  if (objectBounds.empty() || !objectBounds.isFinite())
    throw Error(ErrorKind::Input, "a lattice needs a bounded object (its bounding box is empty or infinite); "
                                  "intersect unbounded shapes with a box or use finite shapes");
  const double cell = cellSize();
  for (int a = 0; a < 3; ++a) {
    const double padded = (objectBounds.hi[a] - objectBounds.lo[a]) + lambda;
    // A box must hold the padded extent in whole cells. The tolerance absorbs
    // rounding in bounds computed through transforms (a sphere of radius 0.5
    // must give exactly 2 cells, not 3).
    const double exact = padded / cell;
    const double cellsReal = std::ceil(exact - 1e-9 * std::max(1.0, exact));
    if (!(cellsReal <= kMaxCells))
      throw Error(ErrorKind::Input,
                  fmt::format("the lattice needs {:.0f} cells along {} but a lattice coordinate is one byte "
                              "(at most {}); use a larger spacing lambda or a smaller oversampling",
                              std::ceil(exact), "xyz"[a], kMaxCells));
    cells_[a] = std::max(1, static_cast<int>(cellsReal));
    // Centre the object when the padded extent is not a whole number of cells.
    const double slack = cells_[a] * cell - padded;
    origin_[a] = objectBounds.lo[a] - 0.5 * lambda - 0.5 * slack;
  }
}

LatticeBox::LatticeBox(std::array<int, 3> cells, double lambda, double oversample, Vec3d originInObject)
    : cells_(cells), lambda_(lambda), oversample_(oversample), origin_(originInObject) {
  checkSpacing(lambda, oversample);
  for (int a = 0; a < 3; ++a)
    if (cells_[a] < 1 || cells_[a] > kMaxCells)
      throw Error(ErrorKind::Input, fmt::format("lattice cell count {} along {} is outside 1..{}", cells_[a],
                                                "xyz"[a], kMaxCells));
}

Mat4d LatticeBox::objectToLattice() const {
  const double k = 1.0 / cellSize();
  Mat4d m(k);
  m[3] = glm::dvec4(-origin_ * k, 1.0);
  return m;
}

Mat4d LatticeBox::latticeToObject() const {
  const double c = cellSize();
  Mat4d m(c);
  m[3] = glm::dvec4(origin_, 1.0);
  return m;
}

std::uint8_t LatticeBox::facesOf(const LatticePoint& p) const {
  const int coord[3] = {p.x, p.y, p.z};
  std::uint8_t mask = 0;
  for (int a = 0; a < 3; ++a) {
    if (coord[a] == 0) mask = static_cast<std::uint8_t>(mask | (1u << (2 * a)));
    if (coord[a] == cells_[a]) mask = static_cast<std::uint8_t>(mask | (1u << (2 * a + 1)));
  }
  return mask;
}

std::vector<LatticePoint> LatticeBox::boundaryPoints() const {
  std::vector<LatticePoint> points;
  for (int x = 0; x <= cells_[0]; ++x)
    for (int y = 0; y <= cells_[1]; ++y)
      for (int z = 0; z <= cells_[2]; ++z) {
        const bool surface = x == 0 || x == cells_[0] || y == 0 || y == cells_[1] || z == 0 || z == cells_[2];
        if (!surface) {
          z = cells_[2] - 1;  // jump straight to the far face along z
          continue;
        }
        points.push_back({static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(z)});
      }
  return points;
}

int LatticeBox::pairMultiplicity(std::uint8_t facesOfIn, std::uint8_t facesOfOut) {
  // Ordered face pairs (A, B), A != B: all combinations minus those with A == B.
  return std::popcount(facesOfIn) * std::popcount(facesOfOut) - std::popcount(static_cast<unsigned>(facesOfIn & facesOfOut));
}

std::uint64_t LatticeBox::pairCountEq13() const {
  const auto points = [](int a, int b) { return std::uint64_t(a + 1) * std::uint64_t(b + 1); };
  const std::uint64_t xy = points(cells_[0], cells_[1]);
  const std::uint64_t yz = points(cells_[1], cells_[2]);
  const std::uint64_t zx = points(cells_[2], cells_[0]);
  return 2 * (4 * (xy * yz + yz * zx + zx * xy) + xy * xy + yz * yz + zx * zx);
}

}  // namespace lattice::lht
