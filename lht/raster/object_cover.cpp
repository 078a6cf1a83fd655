#include "lht/raster/object_cover.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "render/scene/scene.hpp"

namespace lattice::lht {

namespace {

Vec3d apply(const Mat4d& m, const Vec3d& p) { return Vec3d(m * glm::dvec4(p, 1.0)); }

// An upper bound on the largest singular value of m's linear part: the
// square root of the largest Gershgorin row sum of L^T L, which bounds its
// largest eigenvalue. For a similarity it is the scale itself (to rounding).
double stretchBound(const Mat4d& m) {
  double largest = 0.0;
  for (int i = 0; i < 3; ++i) {
    double row = 0.0;
    for (int j = 0; j < 3; ++j) row += std::abs(glm::dot(Vec3d(m[i]), Vec3d(m[j])));
    largest = std::max(largest, row);
  }
  return std::sqrt(largest) * (1.0 + 1e-12);
}

ObjectCover boxCover(const Bounds<double>& box) {
  ObjectCover cover;
  if (box.empty()) return cover;
  if (!box.isFinite())
    cover.unbounded = true;
  else
    cover.boxes.push_back(box);
  return cover;
}

// A shape that states its balls (a capsule, a polyline) is covered by their
// capsules; any other leaf by its box.
ObjectCover leafCover(const LeafDesc& leaf) {
  const std::optional<LeafShape> shape = leaf.shape();
  if (const std::optional<BallChain> balls = shape ? ballsOf(*shape) : std::nullopt)
    return polylineCover(balls->centres, balls->radius);
  return boxCover(leaf.objectBounds());
}

}  // namespace

ObjectCover ObjectCover::mapped(const Mat4d& m) const {
  ObjectCover out;
  out.unbounded = unbounded;
  const double stretch = stretchBound(m);
  for (const CoverCapsule& c : capsules) out.capsules.push_back({apply(m, c.a), apply(m, c.b), c.radius * stretch});
  for (const Bounds<double>& box : boxes) out.boxes.push_back(transformBounds(box, m));
  return out;
}

void ObjectCover::add(const ObjectCover& other) {
  capsules.insert(capsules.end(), other.capsules.begin(), other.capsules.end());
  boxes.insert(boxes.end(), other.boxes.begin(), other.boxes.end());
  unbounded = unbounded || other.unbounded;
}

double ObjectCover::volume() const {
  if (unbounded) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (const CoverCapsule& c : capsules) {
    const Vec3d extent = glm::abs(c.b - c.a) + Vec3d(2.0 * c.radius);
    sum += extent.x * extent.y * extent.z;
  }
  for (const Bounds<double>& box : boxes) {
    const Vec3d extent = box.hi - box.lo;
    sum += extent.x * extent.y * extent.z;
  }
  return sum;
}

ObjectCover coverOf(const NodeDesc& node, const Mat4d& parentToObject) {
  const Mat4d toObject = parentToObject * node.transform;
  if (node.kind == NodeDesc::Kind::Leaf) return node.leaf ? leafCover(*node.leaf).mapped(toObject) : ObjectCover{};
  ObjectCover cover;
  if (node.children.empty()) return cover;  // empty space
  if (node.kind == NodeDesc::Kind::Union) {
    for (const NodeDesc& child : node.children) cover.add(coverOf(child, toObject));
  } else if (node.kind == NodeDesc::Kind::Intersection) {
    cover = coverOf(node.children.front(), toObject);
    for (std::size_t i = 1; i < node.children.size(); ++i) {
      ObjectCover other = coverOf(node.children[i], toObject);
      if (other.volume() < cover.volume()) cover = std::move(other);
    }
  } else {
    cover = coverOf(node.children.front(), toObject);  // a difference lies inside its first operand
  }
  return cover;
}

ObjectCover polylineCover(const std::vector<Vec3d>& points, double radius) {
  ObjectCover cover;
  for (std::size_t i = 1; i < points.size(); ++i) cover.capsules.push_back({points[i - 1], points[i], radius});
  if (points.size() == 1) cover.capsules.push_back({points[0], points[0], radius});
  return cover;
}

}  // namespace lattice::lht
