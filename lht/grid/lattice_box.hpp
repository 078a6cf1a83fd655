#pragma once
// The geometry of a lattice (thesis ch. 2, sec. 2.2): an object, a grid
// spacing lambda and an oversampling factor f_lat >= 1. The lattice box is
// the object's bounding box padded by lambda/2 on every side, divided into
// cells of lambda/f_lat; lattice coordinates count cells from the box's low
// corner, so the grid points on the six faces have integer coordinates
// 0..cells[a] (at most 255 so a coordinate fits in a byte, thesis sec. 2.3).
#include <array>
#include <cstdint>
#include <vector>

#include "foundation/bounds.hpp"
#include "foundation/vec.hpp"

namespace lattice::lht {

// A grid point on the lattice box, in lattice coordinates.
struct LatticePoint {
  std::uint8_t x = 0, y = 0, z = 0;
  friend bool operator==(const LatticePoint&, const LatticePoint&) = default;
  Vec3d toVec() const { return Vec3d(x, y, z); }
};

// The largest lattice coordinate: one byte per coordinate.
inline constexpr int kMaxCells = 255;

class LatticeBox {
 public:
  // objectBounds in object coordinates; lambda > 0, oversample >= 1.
  // Throws lattice::Error(Input) if the bounds are empty or infinite, or the
  // box needs more than 255 cells on an axis.
  LatticeBox(const Bounds<double>& objectBounds, double lambda, double oversample);
  // A box of given cell counts (reading a .lht file); the object-side
  // placement is the caller's business.
  LatticeBox(std::array<int, 3> cells, double lambda, double oversample, Vec3d originInObject);

  const std::array<int, 3>& cells() const { return cells_; }
  double lambda() const { return lambda_; }
  double oversample() const { return oversample_; }
  double cellSize() const { return lambda_ / oversample_; }
  // The object-coordinate position of lattice point (0,0,0).
  const Vec3d& origin() const { return origin_; }

  Mat4d objectToLattice() const;
  Mat4d latticeToObject() const;

  // Faces 0..5: axis = face / 2, side = face % 2 (0: coordinate 0, 1: cells).
  // A point on an edge or corner lies on every face it touches.
  std::uint8_t facesOf(const LatticePoint& p) const;  // bit mask over faces
  bool onBoundary(const LatticePoint& p) const { return facesOf(p) != 0; }
  // Every grid point on the surface of the box, each once.
  std::vector<LatticePoint> boundaryPoints() const;

  // How many times eq. 1.3 counts the ordered pair (pi, po): the number of
  // ordered pairs of distinct faces (A, B) with pi on A and po on B.
  static int pairMultiplicity(std::uint8_t facesOfIn, std::uint8_t facesOfOut);

  // N_lp by eq. 1.3 (closed form).
  std::uint64_t pairCountEq13() const;

 private:
  std::array<int, 3> cells_{};
  double lambda_ = 1.0;
  double oversample_ = 1.0;
  Vec3d origin_{0.0};
};

}  // namespace lattice::lht
