#include "lht/raster/exit_candidates.hpp"

#include <bit>
#include <cmath>

namespace lattice::lht {

ExitCandidates::ExitCandidates(const LatticeBox& box, const std::vector<LatticePoint>& points)
    : cells_(box.cells()), pieces_(points.size(), 0), marked_((points.size() + 63) / 64, 0) {
  for (int face = 0; face < 6; ++face) {
    const int* across = kAcrossAxes[face / 2];
    grid_[face].assign(static_cast<std::size_t>(cells_[across[0]] + 1) * static_cast<std::size_t>(cells_[across[1]] + 1), -1);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint8_t faces = box.facesOf(points[i]);
    if (faces == 0) continue;  // not on the surface: never an exit point
    const int face = std::countr_zero(static_cast<unsigned>(faces));
    const int* across = kAcrossAxes[face / 2];
    const int coord[3] = {points[i].x, points[i].y, points[i].z};
    grid_[face][static_cast<std::size_t>(coord[across[0]]) * static_cast<std::size_t>(cells_[across[1]] + 1) +
                static_cast<std::size_t>(coord[across[1]])] = static_cast<std::int32_t>(i);
  }
}

namespace {

// The grid coordinates 0..cells within [lo, hi]; false when none (NaN bounds
// hold none, as CoverCull::mayTouch's comparisons fail on them).
bool gridRange(double lo, double hi, int cells, int& first, int& last) {
  if (!(lo <= hi) || hi < 0.0 || lo > cells) return false;
  first = lo <= 0.0 ? 0 : static_cast<int>(std::ceil(lo));
  last = hi >= cells ? cells : static_cast<int>(std::floor(hi));
  return first <= last;
}

}  // namespace

void ExitCandidates::collect(const CoverCull& cull, const CoverCull::Fan& fan, std::uint8_t facesOfP,
                             std::vector<Candidate>& out) {
  out.clear();
  const std::size_t n = cull.pieces();
  for (int face = 0; face < 6; ++face) {
    if (facesOfP & (1u << face)) continue;  // the fan has no rectangles there
    const int* across = kAcrossAxes[face / 2];
    const int stride = cells_[across[1]] + 1;
    const std::vector<std::int32_t>& grid = grid_[face];
    const double* rect = &fan.rects[static_cast<std::size_t>(face) * n * 4];
    for (std::size_t k = 0; k < n; ++k, rect += 4) {
      int u0, u1, v0, v1;
      if (!gridRange(rect[0], rect[1], cells_[across[0]], u0, u1) || !gridRange(rect[2], rect[3], cells_[across[1]], v0, v1))
        continue;
      const std::uint64_t bit = std::uint64_t(1) << k;
      for (int u = u0; u <= u1; ++u)
        for (int v = v0; v <= v1; ++v) {
          const std::int32_t point = grid[static_cast<std::size_t>(u * stride + v)];
          if (point < 0) continue;
          pieces_[static_cast<std::size_t>(point)] |= bit;
          marked_[static_cast<std::size_t>(point) / 64] |= std::uint64_t(1) << (point % 64);
        }
    }
  }
  for (std::size_t w = 0; w < marked_.size(); ++w) {
    for (std::uint64_t bits = marked_[w]; bits != 0; bits &= bits - 1) {
      const std::size_t point = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
      out.push_back({static_cast<std::uint32_t>(point), pieces_[point]});
      pieces_[point] = 0;
    }
    marked_[w] = 0;
  }
}

}  // namespace lattice::lht
