#include "lht/raster/cover_cull.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace lattice::lht {

namespace {

constexpr double kRectSlack = 1e-6;   // cells: the rectangles' own rounding
constexpr double kSliverReach = 0.25;  // cells: how near p a cut-off sliver may lie
// Cells: the balls' rectangles' rounding, far above it (a square root and a
// quotient of terms under 255^2 cells) and far below a grid step.
constexpr double kBallSlack = 1e-4;

double distanceToBox(const Vec3d& p, const Bounds<double>& box) {
  const Vec3d outside = glm::max(glm::max(box.lo - p, p - box.hi), Vec3d(0.0));
  return glm::length(outside);
}

}  // namespace

CoverCull::CoverCull(const ObjectCover& cover, const std::array<int, 3>& cells, double margin)
    : active_(!cover.unbounded), cells_(cells) {
  diagonal_ = glm::length(Vec3d(cells[0], cells[1], cells[2]));
  for (const CoverCapsule& c : cover.capsules) {
    const double reach = c.radius + margin;
    capsules_.push_back({c.a, c.b - c.a, reach, reach * reach});
    grown_.push_back({glm::min(c.a, c.b) - Vec3d(reach), glm::max(c.a, c.b) + Vec3d(reach)});
  }
  for (const Bounds<double>& b : cover.boxes) {
    boxes_.push_back({b.center(), (b.hi - b.lo) * 0.5 + Vec3d(margin)});
    grown_.push_back({b.lo - Vec3d(margin), b.hi + Vec3d(margin)});
  }
  if (pieces() > kMaxCoverPieces) active_ = false;
}

bool CoverCull::touches(std::size_t piece, const Vec3d& p, const Vec3d& d) const {
  if (piece < capsules_.size()) {
    const Capsule& c = capsules_[piece];
    const Vec3d a = glm::cross(c.a - p, d);
    const Vec3d b = glm::cross(c.axis, d);
    const double ab = glm::dot(a, b), bb = glm::dot(b, b);
    // The t in [0, 1] minimising |a + t b|^2 (convex in t).
    const double t = ab >= 0.0 ? 0.0 : (-ab >= bb ? 1.0 : -ab / bb);
    const Vec3d g = a + t * b;
    return glm::dot(g, g) <= c.reach2 * glm::dot(d, d);
  }
  const Box& box = boxes_[piece - capsules_.size()];
  const Vec3d r = box.centre - p, ad = glm::abs(d);
  return std::abs(r.y * d.z - r.z * d.y) <= box.half.y * ad.z + box.half.z * ad.y &&
         std::abs(r.z * d.x - r.x * d.z) <= box.half.z * ad.x + box.half.x * ad.z &&
         std::abs(r.x * d.y - r.y * d.x) <= box.half.x * ad.y + box.half.y * ad.x;
}

bool CoverCull::mayTouch(const Vec3d& p, const Vec3d& q) const {
  if (!active_) return true;
  const Vec3d d = q - p;
  for (std::size_t k = 0; k < pieces(); ++k)
    if (touches(k, p, d)) return true;
  return false;
}

void CoverCull::aim(const Vec3d& p, std::uint8_t facesOfP, Fan& fan) const {
  fan.p = p;
  const std::size_t n = pieces();
  fan.rects.assign(6 * n * 4, 0.0);
  if (!active_) return;
  const double inf = std::numeric_limits<double>::infinity();
  const double delta = kSliverReach / std::max(1.0, diagonal_);
  for (int face = 0; face < 6; ++face) {
    if (facesOfP & (1u << face)) continue;  // pairs sharing a face are never asked
    const int axis = face / 2;
    const int across[2] = {kAcrossAxes[axis][0], kAcrossAxes[axis][1]};
    const double plane = (face % 2) ? cells_[axis] : 0.0;
    const double toPlane = plane - p[axis];  // at least one cell
    const double side = toPlane > 0 ? 1.0 : -1.0;
    for (std::size_t k = 0; k < n; ++k) {
      double* rect = &fan.rects[(static_cast<std::size_t>(face) * n + k) * 4];
      const Bounds<double>& box = grown_[k];
      // The box's extent along the axis, as distances in front of p.
      const double lo = (box.lo[axis] - p[axis]) * side, hi = (box.hi[axis] - p[axis]) * side;
      double near = std::min(lo, hi);
      const double far = std::max(lo, hi);
      if (far <= 0.0) {  // wholly behind p: no segment towards this face reaches it
        rect[0] = inf, rect[1] = -inf, rect[2] = inf, rect[3] = -inf;
        continue;
      }
      if (near < delta) {
        if (distanceToBox(p, box) <= kSliverReach) {
          rect[0] = -inf, rect[1] = inf, rect[2] = -inf, rect[3] = inf;
          continue;
        }
        near = delta;
      }
      // Central projection from p: a point h in front of p lands at
      // p + (x - p) |toPlane| / h; over the box the extremes lie at the
      // nearest or the farthest h and the box's low or high side.
      const double scales[2] = {std::abs(toPlane) / near, std::abs(toPlane) / far};
      for (int i = 0; i < 2; ++i) {
        double low = inf, high = -inf;
        for (const double s : scales)
          for (const double x : {box.lo[across[i]], box.hi[across[i]]}) {
            const double at = p[across[i]] + (x - p[across[i]]) * s;
            low = std::min(low, at);
            high = std::max(high, at);
          }
        rect[2 * i] = low - kRectSlack;
        rect[2 * i + 1] = high + kRectSlack;
      }
      if (k < capsules_.size()) narrowToBalls(capsules_[k], p, axis, side, std::abs(toPlane), rect);
    }
  }
}

// A capsule is the hull of its end balls, and from a point behind both (along
// the face's axis) its shadow on the face is the hull of theirs, whose box is
// the box of the two shadows. A ball's shadow along an across axis u spans
// the slopes m of the two lines from p tangent to its disc in the (axis, u)
// plane, centre (h, x) in front of p: (m h - x)^2 = R^2 (m^2 + 1), so
// m = (h x -+ R sqrt(h^2 + x^2 - R^2)) / (h^2 - R^2). Both balls must lie
// kSliverReach beyond p's plane, where these are well conditioned; else the
// box's rectangle stands. A diagonal capsule's rectangle shrinks the most.
void CoverCull::narrowToBalls(const Capsule& c, const Vec3d& p, int axis, double side, double toPlane, double* rect) {
  const Vec3d ends[2] = {c.a, c.a + c.axis};
  double h[2];
  for (int e = 0; e < 2; ++e) {
    h[e] = (ends[e][axis] - p[axis]) * side;
    if (!(h[e] - c.reach > kSliverReach)) return;
  }
  for (int i = 0; i < 2; ++i) {
    const int u = kAcrossAxes[axis][i];
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int e = 0; e < 2; ++e) {
      const double x = ends[e][u] - p[u];
      const double root = c.reach * std::sqrt(h[e] * h[e] + x * x - c.reach2);
      const double across = h[e] * h[e] - c.reach2;
      low = std::min(low, (h[e] * x - root) / across);
      high = std::max(high, (h[e] * x + root) / across);
    }
    rect[2 * i] = std::max(rect[2 * i], p[u] + low * toPlane - kBallSlack);
    rect[2 * i + 1] = std::min(rect[2 * i + 1], p[u] + high * toPlane + kBallSlack);
  }
}

bool CoverCull::mayTouch(const Fan& fan, const Vec3d& q, std::uint8_t facesOfQ) const {
  if (!active_) return true;
  const int face = std::countr_zero(static_cast<unsigned>(facesOfQ));
  const int axis = face / 2;
  const double qu = q[kAcrossAxes[axis][0]], qv = q[kAcrossAxes[axis][1]];
  const std::size_t n = pieces();
  const double* rect = &fan.rects[static_cast<std::size_t>(face) * n * 4];
  const Vec3d d = q - fan.p;
  for (std::size_t k = 0; k < n; ++k, rect += 4)
    if (qu >= rect[0] && qu <= rect[1] && qv >= rect[2] && qv <= rect[3] && touches(k, fan.p, d)) return true;
  return false;
}

bool CoverCull::touchesAlong(std::size_t piece, const Vec3d& p, const Vec3d& d, double& along) const {
  if (piece >= capsules_.size()) {
    along = glm::dot(boxes_[piece - capsules_.size()].centre - p, d);
    return touches(piece, p, d);
  }
  const Capsule& c = capsules_[piece];
  const Vec3d a = glm::cross(c.a - p, d);
  const Vec3d b = glm::cross(c.axis, d);
  const double ab = glm::dot(a, b), bb = glm::dot(b, b);
  const double t = ab >= 0.0 ? 0.0 : (-ab >= bb ? 1.0 : -ab / bb);  // as touches() finds it
  const Vec3d g = a + t * b;
  along = glm::dot(c.a + t * c.axis - p, d);
  return glm::dot(g, g) <= c.reach2 * glm::dot(d, d);
}

std::size_t CoverCull::touching(const Fan& fan, const Vec3d& q, std::uint64_t pieces, Near* out) const {
  const Vec3d d = q - fan.p;
  std::size_t n = 0;
  for (; pieces != 0; pieces &= pieces - 1) {
    const auto k = static_cast<std::uint32_t>(std::countr_zero(pieces));
    double along;
    if (touchesAlong(k, fan.p, d, along)) out[n++] = {k, along};
  }
  return n;
}

bool CoverCull::mayTouch(const Fan& fan, const Vec3d& q, std::uint64_t pieces) const {
  if (!active_) return true;
  const Vec3d d = q - fan.p;
  for (; pieces != 0; pieces &= pieces - 1)  // lowest piece first, as the rectangles are tried
    if (touches(static_cast<std::size_t>(std::countr_zero(pieces)), fan.p, d)) return true;
  return false;
}

}  // namespace lattice::lht
