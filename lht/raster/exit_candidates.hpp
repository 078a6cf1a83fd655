#pragma once
// The exit points a fan of the cover cull (lht/raster/cover_cull.hpp) may
// reach, found from the fan's rectangles instead of by testing every exit
// point against every rectangle.
//
// Method: each face's grid points are indexed by their (u, v) on it, so a
// piece's rectangle on a face names the points inside it directly; each point
// collects the mask of the pieces whose rectangle on its lowest face holds it
// (the face CoverCull::mayTouch reads), and the marked points are handed out
// in the order of the box's boundary points. Why: a row of the scene hair's
// 380 points tested 9 rectangles at each of them, where about one point in
// four lies in any; the rasterizer then asks the exact test only for the
// pieces marked, and counts the pairs it never visits by their faces.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lht/grid/lattice_box.hpp"
#include "lht/raster/cover_cull.hpp"

namespace lattice::lht {

class ExitCandidates {
 public:
  struct Candidate {
    std::uint32_t point;  // index into the boundary points
    std::uint64_t pieces;  // bit k: piece k's rectangle holds the point
  };

  // `points`: box.boundaryPoints(), whose indices the candidates give.
  ExitCandidates(const LatticeBox& box, const std::vector<LatticePoint>& points);

  // The points whose lowest face p is not on and a rectangle of `fan` (aimed
  // from a point on the faces `facesOfP`) holds there, in increasing index:
  // the points for which CoverCull::mayTouch(fan, q, faces of q) would ask an
  // exact test (the caller drops those sharing another face with p). `out`
  // is overwritten.
  void collect(const CoverCull& cull, const CoverCull::Fan& fan, std::uint8_t facesOfP, std::vector<Candidate>& out);

 private:
  std::array<int, 3> cells_{};
  // Per face: the index of the point at (u, v), at u * (cells[v] + 1) + v;
  // -1 where that point's lowest face is another.
  std::array<std::vector<std::int32_t>, 6> grid_;
  std::vector<std::uint64_t> pieces_;  // per point; zero between calls
  std::vector<std::uint64_t> marked_;  // a bit per point; zero between calls
};

}  // namespace lattice::lht
