#include "lht/cover_cull.hpp"

#include <algorithm>
#include <cmath>

namespace lattice::lht {

CoverCull::CoverCull(const ObjectCover& cover, double margin) : active_(!cover.unbounded) {
  for (const CoverCapsule& c : cover.capsules) {
    const double reach = c.radius + margin;
    capsules_.push_back({c.a, c.b - c.a, reach * reach});
  }
  for (const Bounds<double>& b : cover.boxes) boxes_.push_back({b.center(), (b.hi - b.lo) * 0.5 + Vec3d(margin)});
}

bool CoverCull::mayTouch(const Vec3d& p, const Vec3d& q) const {
  if (!active_) return true;
  const Vec3d d = q - p;
  const double dd = glm::dot(d, d);
  for (const Capsule& c : capsules_) {
    const Vec3d a = glm::cross(c.a - p, d);
    const Vec3d b = glm::cross(c.axis, d);
    const double ab = glm::dot(a, b), bb = glm::dot(b, b);
    // The t in [0, 1] minimising |a + t b|^2 (f is convex in t).
    const double t = ab >= 0.0 ? 0.0 : (-ab >= bb ? 1.0 : -ab / bb);
    const Vec3d g = a + t * b;
    if (glm::dot(g, g) <= c.reach2 * dd) return true;
  }
  const Vec3d ad = glm::abs(d);
  for (const Box& box : boxes_) {
    const Vec3d r = box.centre - p;
    if (std::abs(r.y * d.z - r.z * d.y) > box.half.y * ad.z + box.half.z * ad.y) continue;
    if (std::abs(r.z * d.x - r.x * d.z) > box.half.z * ad.x + box.half.x * ad.z) continue;
    if (std::abs(r.x * d.y - r.y * d.x) > box.half.x * ad.y + box.half.y * ad.x) continue;
    return true;
  }
  return false;
}

}  // namespace lattice::lht
