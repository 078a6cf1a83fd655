#include "bench/peers/peer_scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>
#include <variant>

#include "exporter/quartic_forms.hpp"
#include "foundation/error.hpp"
#include "foundation/overloaded.hpp"

namespace lattice::peers {

namespace {

// The scale of a similarity transform (rotation x uniform scale + shift), or
// nothing: a sphere or tube under any other map is no longer one.
std::optional<double> similarityScale(const Mat4d& m) {
  const Vec3d a(m[0]), b(m[1]), c(m[2]);
  const double s = glm::length(a);
  const double tol = 1e-9 * s;
  if (std::abs(glm::length(b) - s) > tol || std::abs(glm::length(c) - s) > tol) return std::nullopt;
  if (std::abs(glm::dot(a, b)) > tol * s || std::abs(glm::dot(a, c)) > tol * s || std::abs(glm::dot(b, c)) > tol * s)
    return std::nullopt;
  return s;
}

Vec3d apply(const Mat4d& m, const Vec3d& p) { return Vec3d(m * glm::dvec4(p, 1.0)); }

class Flattener {
 public:
  explicit Flattener(PeerScene& out) : out_(out) {}

  // inLattice: building a shared object, whose parts keep an unset material
  // unless its own nodes set one.
  void node(const NodeDesc& n, const Mat4d& parent, std::optional<MaterialId> material, PeerObject& into,
            bool inLattice) {
    const Mat4d toWorld = parent * n.transform;
    if (n.material) material = n.material;
    if (n.kind != NodeDesc::Kind::Leaf && n.kind != NodeDesc::Kind::Union)
      refuse(n, "an intersection or difference (Embree has no CSG)");
    if (n.kind == NodeDesc::Kind::Union) {
      for (const NodeDesc& child : n.children) node(child, toWorld, material, into, inLattice);
      return;
    }
    const std::optional<LeafShape> shape = n.leaf->shape();
    if (!shape) refuse(n, n.leaf->describe());
    // One case per shape and no default: a new shape fails to compile here.
    std::visit(Overloaded{
                   [&](const QuarticShape& s) { quartic(n, s, toWorld, material, into, inLattice); },
                   [&](const CapsuleShape& s) {
                     tube(n, {Vec3d(0.0), Vec3d(0.0, 0.0, s.length)}, s.radius, toWorld, material, into);
                   },
                   [&](const PolylineShape& s) { tube(n, s.points, s.radius, toWorld, material, into); },
                   [&](const LatticeShape& s) { lattice(n, s, toWorld, material, inLattice); },
               },
               *shape);
  }

 private:
  [[noreturn]] static void refuse(const NodeDesc& n, const std::string& what) {
    throw Error(ErrorKind::Input, fmt::format("{}: the Embree peer cannot trace {}; it traces unions of spheres, "
                                              "planes, polylines, capsules and lattices of those",
                                              n.origin.empty() ? std::string("scene") : n.origin, what));
  }

  void quartic(const NodeDesc& n, const QuarticShape& q, const Mat4d& toWorld, std::optional<MaterialId> material,
               PeerObject& into, bool inLattice) {
    const exporter::QuarticForm form = exporter::classifyQuartic(q.f);
    if (form.kind == exporter::QuarticForm::Kind::Sphere) {
      const auto s = similarityScale(toWorld);
      if (!s) refuse(n, "a sphere under a transform that is not a similarity");
      into.spheres.push_back({apply(toWorld, form.centre), form.radius * *s, material});
      return;
    }
    if (form.kind == exporter::QuarticForm::Kind::Plane && !inLattice) {
      // A point of the plane and the normal's image (inverse transpose).
      const Vec3d point = apply(toWorld, form.normal * form.offset);
      const Vec3d normal = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(toWorld))) * form.normal);
      out_.planes.push_back({normal, glm::dot(normal, point), material.value_or(0)});
      return;
    }
    refuse(n, n.leaf->describe() + " (only spheres and, outside lattices, half-spaces have closed forms here)");
  }

  void tube(const NodeDesc& n, const std::vector<Vec3d>& points, double radius, const Mat4d& toWorld,
            std::optional<MaterialId> material, PeerObject& into) {
    const auto s = similarityScale(toWorld);
    if (!s) refuse(n, "a tube under a transform that is not a similarity");
    if (points.size() == 2 && points[0] == points[1]) {  // a capsule of length 0 (a scene's sphere) is a ball
      into.spheres.push_back({apply(toWorld, points[0]), radius * *s, material});
      return;
    }
    PeerTube t{{}, radius * *s, material};
    for (const Vec3d& p : points) t.points.push_back(apply(toWorld, p));
    into.tubes.push_back(std::move(t));
  }

  void lattice(const NodeDesc& n, const LatticeShape& shape, const Mat4d& toWorld, std::optional<MaterialId> material,
               bool inLattice) {
    if (inLattice) refuse(n, "a lattice inside a lattice's object");
    if (!shape.castsShadows) refuse(n, fmt::format("lattice '{}' with shadows = false", shape.name));
    auto [it, added] = shared_.try_emplace(shape.object, out_.shared.size());
    if (added) {
      out_.shared.emplace_back();
      PeerObject object;
      node(*shape.object, Mat4d(1.0), std::nullopt, object, true);
      out_.shared[it->second] = std::move(object);
    }
    out_.instances.push_back({it->second, toWorld, material.value_or(0)});
  }

  PeerScene& out_;
  std::map<const NodeDesc*, std::size_t> shared_;
};

}  // namespace

PeerScene flattenScene(const SceneDesc& scene) {
  PeerScene out;
  Flattener(out).node(scene.root, Mat4d(1.0), MaterialId(0), out.world, false);
  return out;
}

}  // namespace lattice::peers
