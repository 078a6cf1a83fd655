#pragma once
// The grid points on a lattice box's surface, numbered 0..count()-1 in the
// order LatticeBox::boundaryPoints() lists them (x outermost, then y, then
// z), so the ordered pairs (p_i, p_o) of a lattice are the integers
// i * count() + o: an enumerable index space (thesis sec. 5.2.1) for the
// compressed table (lht/table/compressed_table.hpp) and the look-up statistics
// (lht/leaf/lookup_stats.hpp).
//
// Method: the box's surface is the x = 0 face, then one ring of the y-z
// rectangle per inner x slice, then the x = cells face; indexOf() is a few
// comparisons and multiplications, no table, so it costs no memory per box
// and no cache line per look-up.
#include <array>
#include <cstdint>

#include "lht/grid/lattice_box.hpp"

namespace lattice::lht {

class BoundaryIndex {
 public:
  static constexpr std::uint32_t kNotOnBoundary = 0xFFFFFFFFu;

  explicit BoundaryIndex(const std::array<int, 3>& cells);

  std::uint32_t count() const { return count_; }
  std::array<int, 3> cells() const { return {nx_, ny_, nz_}; }
  // The point's number, or kNotOnBoundary for a point inside or outside the box.
  std::uint32_t indexOf(const LatticePoint& p) const {
    const int x = p.x, y = p.y, z = p.z;
    if (x > nx_ || y > ny_ || z > nz_) return kNotOnBoundary;
    if (x == 0) return static_cast<std::uint32_t>(y * (nz_ + 1) + z);
    if (x == nx_) return face_ + static_cast<std::uint32_t>(nx_ - 1) * ring_ + static_cast<std::uint32_t>(y * (nz_ + 1) + z);
    const std::uint32_t slice = face_ + static_cast<std::uint32_t>(x - 1) * ring_;
    if (y == 0) return slice + static_cast<std::uint32_t>(z);
    if (y == ny_) return slice + static_cast<std::uint32_t>((nz_ + 1) + 2 * (ny_ - 1) + z);
    if (z == 0) return slice + static_cast<std::uint32_t>((nz_ + 1) + 2 * (y - 1));
    if (z == nz_) return slice + static_cast<std::uint32_t>((nz_ + 1) + 2 * (y - 1) + 1);
    return kNotOnBoundary;
  }
  // The point numbered `index` (< count()).
  LatticePoint pointAt(std::uint32_t index) const;

 private:
  int nx_, ny_, nz_;
  std::uint32_t face_;   // points on the x = 0 face: (ny + 1)(nz + 1)
  std::uint32_t ring_;   // points on one inner x slice's ring
  std::uint32_t count_;
};

}  // namespace lattice::lht
