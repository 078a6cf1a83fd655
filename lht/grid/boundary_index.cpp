#include "lht/grid/boundary_index.hpp"

namespace lattice::lht {

BoundaryIndex::BoundaryIndex(const std::array<int, 3>& cells)
    : nx_(cells[0]), ny_(cells[1]), nz_(cells[2]),
      face_(static_cast<std::uint32_t>((cells[1] + 1) * (cells[2] + 1))),
      ring_(static_cast<std::uint32_t>(2 * (cells[2] + 1) + 2 * (cells[1] - 1))),
      count_(2 * face_ + static_cast<std::uint32_t>(cells[0] - 1) * ring_) {}

LatticePoint BoundaryIndex::pointAt(std::uint32_t index) const {
  const auto point = [](int x, int y, int z) {
    return LatticePoint{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(z)};
  };
  const int columns = nz_ + 1;
  if (index < face_) return point(0, static_cast<int>(index) / columns, static_cast<int>(index) % columns);
  const std::uint32_t inner = static_cast<std::uint32_t>(nx_ - 1) * ring_;
  if (index >= face_ + inner) {
    const int at = static_cast<int>(index - face_ - inner);
    return point(nx_, at / columns, at % columns);
  }
  const int x = 1 + static_cast<int>((index - face_) / ring_);
  const int at = static_cast<int>((index - face_) % ring_);
  if (at < columns) return point(x, 0, at);
  const int middle = at - columns;
  if (middle < 2 * (ny_ - 1)) return point(x, 1 + middle / 2, middle % 2 ? nz_ : 0);
  return point(x, ny_, middle - 2 * (ny_ - 1));
}

}  // namespace lattice::lht
