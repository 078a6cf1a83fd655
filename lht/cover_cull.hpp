#pragma once
// Culling a lattice segment against its object's cover (lht/object_cover.hpp)
// before tracing it: a segment whose line stays farther than a margin from
// every piece of the cover cannot touch the object, nor can the four
// segments the rasterizer shifts sideways by the graze tolerance to catch
// tangents, so the pair is a miss without a trace. A segment that may touch
// is traced as before, so the table is the one an uncovered rasterizer
// builds, byte for byte.
//
// Method: the line, not the segment, is tested (a superset: cheaper, and the
// same thing for the rasterizer, whose segments run from face to face of the
// box around the object). Line to capsule: the squared distance from the
// axis point a + t(b - a) to the line is |(a - p) x d + t (b - a) x d|^2 /
// |d|^2, a quadratic in t minimised over [0, 1]; evaluated from the two cross
// products (never as a difference of squared lengths) its rounding stays
// near 1e-10 cells in a 255-cell box. Line to box: the separating axes of a
// line and a box are the three d x e_k.
//
// Tunables: kCoverMargin, the distance in cells a line must keep from the
// cover to be culled: 1e-4, a thousand times the graze tolerance (1e-7
// cells) and six orders above the tests' rounding. A larger margin only
// traces a few more near misses.
#include <vector>

#include "lht/object_cover.hpp"

namespace lattice::lht {

inline constexpr double kCoverMargin = 1e-4;

class CoverCull {
 public:
  CoverCull() = default;  // culls nothing
  // `cover` in the coordinates of the segments (lattice coordinates).
  explicit CoverCull(const ObjectCover& cover, double margin = kCoverMargin);

  // False only if the line through p and q (p != q) stays clear of the cover.
  bool mayTouch(const Vec3d& p, const Vec3d& q) const;

 private:
  struct Capsule {
    Vec3d a, axis;  // axis = b - a
    double reach2;  // (radius + margin)^2
  };
  struct Box {
    Vec3d centre, half;  // half extents grown by the margin
  };
  bool active_ = false;
  std::vector<Capsule> capsules_;
  std::vector<Box> boxes_;
};

}  // namespace lattice::lht
