#pragma once
// Culling a lattice segment against its object's cover (lht/raster/object_cover.hpp)
// before tracing it: a segment that stays farther than a margin from every
// piece of the cover cannot touch the object, nor can the four segments the
// rasterizer shifts sideways by the graze tolerance to catch tangents, so the
// pair is a miss without a trace. A segment that may touch is traced as
// before, so the table is the one an uncovered rasterizer builds, byte for
// byte.
//
// Method, two stages:
// * A fan per entry point p (all the segments leaving p, built once for its
//   1,400-odd exit points on the scene hair at f_lat 2): each piece's box,
//   grown by the margin, seen from p on the plane of each face p is not on,
//   as a rectangle of that face. An exit point q outside a piece's rectangle
//   is not behind that piece. The box's part within delta of p's plane along
//   the face's axis would project without bound; it is cut off where it lies
//   farther than 0.25 cells from p, which no segment can reach through that
//   sliver (a segment's point within delta of p's plane along the axis is
//   within delta times the box diagonal of p, the face being at least one
//   cell from p), and otherwise the rectangle is the whole face.
// * The exact distance of the segment's line to each piece whose rectangle
//   holds q. Line to capsule: the squared distance from the axis point
//   a + t(b - a) to the line is |(a - p) x d + t (b - a) x d|^2 / |d|^2, a
//   quadratic in t minimised over [0, 1]; evaluated from the two cross
//   products (never as a difference of squared lengths) its rounding stays
//   near 1e-10 cells in a 255-cell box. Line to box: the separating axes of a
//   line and a box are the three d x e_k. The line holds the segment, so
//   this errs only towards tracing.
//
// Tunables: kCoverMargin, the distance in cells a segment must keep from the
// cover to be culled: 1e-4, a thousand times the graze tolerance (1e-7
// cells) and six orders above the tests' rounding; a larger margin only
// traces a few more near misses (22 of 2.1 million pairs on the scene hair).
// The rectangles are widened by 1e-6 cells for their own rounding.
// kMaxCoverPieces: a cover of more pieces culls nothing, since every pair
// would test every piece's rectangle, where the object's BVH finds a miss
// in a few box tests; lattice objects are a few to tens of pieces.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lht/raster/object_cover.hpp"

namespace lattice::lht {

inline constexpr double kCoverMargin = 1e-4;
inline constexpr std::size_t kMaxCoverPieces = 64;  // a piece is one bit of a 64-bit mask

// The two axes spanning the faces across `axis`, in order: a face's u and v.
inline constexpr int kAcrossAxes[3][2] = {{1, 2}, {0, 2}, {0, 1}};

class CoverCull {
 public:
  CoverCull() = default;  // culls nothing
  // `cover` in lattice coordinates, for a box of `cells`.
  CoverCull(const ObjectCover& cover, const std::array<int, 3>& cells, double margin = kCoverMargin);

  bool active() const { return active_; }

  // False only if the line through p and q (p != q) stays clear of the cover.
  bool mayTouch(const Vec3d& p, const Vec3d& q) const;

  // The segments leaving one point of the box's surface.
  struct Fan {
    Vec3d p{0.0};
    // Per face, per piece: u0, u1, v0, v1, at rects[(face * pieces + piece) * 4],
    // u and v the face's axes in acrossAxes order: the exit points of that
    // face whose segment from p may touch the piece lie within them.
    std::vector<double> rects;
  };
  // Prepares `fan` for p (on the faces `facesOfP`), reusing its storage.
  void aim(const Vec3d& p, std::uint8_t facesOfP, Fan& fan) const;
  // False only if the segment from fan.p to q (on the faces `facesOfQ`,
  // none of them shared with p) stays clear of the cover.
  bool mayTouch(const Fan& fan, const Vec3d& q, std::uint8_t facesOfQ) const;
  // The same for an exit point whose lowest face's rectangles hold it for the
  // pieces in `pieces` (bit k: piece k) and no other (lht/raster/exit_candidates.hpp).
  bool mayTouch(const Fan& fan, const Vec3d& q, std::uint64_t pieces) const;
  // Of `pieces`, those the segment from fan.p to q may touch: every piece
  // not among them it stays clear of (an active cull only). Each is written
  // to `out` (room for every piece) with how far along the segment it lies
  // nearest (in units of |q - p|^2: an order, not a distance); returns how many.
  struct Near {
    std::uint32_t piece;
    double along;
  };
  std::size_t touching(const Fan& fan, const Vec3d& q, std::uint64_t pieces, Near* out) const;

  std::size_t pieces() const { return capsules_.size() + boxes_.size(); }

 private:
  struct Capsule {
    Vec3d a, axis;  // axis = b - a
    double reach;   // radius + margin
    double reach2;  // reach^2
  };
  struct Box {
    Vec3d centre, half;  // half extents grown by the margin
  };
  // Pieces are the capsules, then the boxes, numbered in that order.
  bool touches(std::size_t piece, const Vec3d& p, const Vec3d& d) const;
  // Narrows a capsule's rectangle to the box of its end balls' shadows.
  static void narrowToBalls(const Capsule& c, const Vec3d& p, int axis, double side, double toPlane, double* rect);
  // touches(), and where along d the piece lies nearest.
  bool touchesAlong(std::size_t piece, const Vec3d& p, const Vec3d& d, double& along) const;

  bool active_ = false;
  std::array<int, 3> cells_{};
  double diagonal_ = 0.0;
  std::vector<Capsule> capsules_;
  std::vector<Box> boxes_;
  std::vector<Bounds<double>> grown_;  // each piece's box, grown by the margin
};

}  // namespace lattice::lht
