#include "exporter/pov_objects.hpp"

#include <fmt/format.h>

#include <optional>
#include <variant>

#include "exporter/pov_format.hpp"
#include "exporter/quartic_forms.hpp"
#include "foundation/error.hpp"
#include "foundation/overloaded.hpp"

namespace lattice::exporter {

namespace {

std::string indent(int depth) { return std::string(static_cast<std::size_t>(depth) * 2, ' '); }

// The texture and the transform, written last inside an object's braces.
std::string modifiersFor(MaterialId material, const Mat4d& transform) {
  if (isIdentity(transform)) return fmt::format("texture {{ {} }}", povMaterialName(material));
  return fmt::format("texture {{ {} }} {}", povMaterialName(material), povMatrix(transform));
}

const char* povOperation(NodeDesc::Kind kind) {
  switch (kind) {
    case NodeDesc::Kind::Intersection: return "intersection";
    case NodeDesc::Kind::Difference: return "difference";
    default: return "union";
  }
}

}  // namespace

void PovObjectWriter::write(const NodeDesc& root, MaterialId inherited) { node(objects_, root, inherited, 0); }

void PovObjectWriter::node(std::string& out, const NodeDesc& n, MaterialId inherited, int depth,
                           const std::string& parentOrigin) {
  const MaterialId material = n.material.value_or(inherited);
  const std::string& origin = n.origin.empty() ? parentOrigin : n.origin;
  if (n.kind == NodeDesc::Kind::Leaf) return leaf(out, n, material, depth, origin);
  if (n.children.empty()) {  // an empty union is empty space: nothing to write
    out += fmt::format("{}// an empty set operation ({})\n", indent(depth), n.origin);
    return;
  }
  out += fmt::format("{}{} {{ // {}\n", indent(depth), povOperation(n.kind), n.origin);
  for (const NodeDesc& child : n.children) node(out, child, material, depth + 1, origin);
  if (!isIdentity(n.transform)) out += fmt::format("{}{}\n", indent(depth + 1), povMatrix(n.transform));
  out += fmt::format("{}}}\n", indent(depth));
}

void PovObjectWriter::leaf(std::string& out, const NodeDesc& n, MaterialId material, int depth,
                           const std::string& origin) {
  const std::string where = origin.empty() ? source_.string() : origin;
  if (!n.leaf) throw Error(ErrorKind::Internal, fmt::format("{}: leaf node without a leaf description", where));
  const std::optional<LeafShape> shape = n.leaf->shape();
  if (!shape)
    throw Error(ErrorKind::Input, fmt::format("{}: {} cannot be written for POV-Ray (its leaf type does not describe "
                                              "its shape); remove it from the scene or export another scene",
                                              where, n.leaf->describe()));
  const std::string modifiers = modifiersFor(material, n.transform);
  // One case per shape and no default: a new shape fails to compile here.
  std::visit(Overloaded{
                 [&](const QuarticShape& s) { quartic(out, s, modifiers, depth); },
                 [&](const CapsuleShape& s) {
                   tube(out, {Vec3d(0.0), Vec3d(0.0, 0.0, s.length)}, s.radius, modifiers, depth);
                 },
                 [&](const PolylineShape& s) { tube(out, s.points, s.radius, modifiers, depth); },
                 [&](const LatticeShape& s) {
                   std::string placed;
                   if (!isIdentity(n.transform)) placed = fmt::format(" {}", povMatrix(n.transform));
                   if (!s.castsShadows) placed += " no_shadow";
                   out += fmt::format("{}object {{ {}{} }}\n", indent(depth), latticeName(s, material, where), placed);
                 },
             },
             *shape);
}

void PovObjectWriter::quartic(std::string& out, const QuarticShape& shape, const std::string& modifiers, int depth) {
  const QuarticForm form = classifyQuartic(shape.f);
  const std::string pad = indent(depth);
  // POV-Ray takes quadrics and quartics as infinite; a finite box saves it work.
  std::string bounded;
  if (shape.bounds.isFinite())
    bounded = fmt::format(" bounded_by {{ box {{ {}, {} }} }}", povVector(shape.bounds.lo), povVector(shape.bounds.hi));
  switch (form.kind) {
    case QuarticForm::Kind::Plane:
      out += fmt::format("{}plane {{ {}, {} {} }}\n", pad, povVector(form.normal), povNumber(form.offset), modifiers);
      return;
    case QuarticForm::Kind::Sphere:
      out += fmt::format("{}sphere {{ {}, {} {} }}\n", pad, povVector(form.centre), povNumber(form.radius), modifiers);
      return;
    case QuarticForm::Kind::Quadric: {
      const auto& q = form.quadric;
      out += fmt::format("{}quadric {{ {}, {}, {}, {}{} {} }}\n", pad, povVector({q[0], q[1], q[2]}),
                         povVector({q[3], q[4], q[5]}), povVector({q[6], q[7], q[8]}), povNumber(q[9]), bounded,
                         modifiers);
      return;
    }
    case QuarticForm::Kind::Torus:
      // POV-Ray's torus goes round its y axis, ours round z: a quarter turn
      // about x takes POV's y onto our z first.
      out += fmt::format("{}torus {{ {}, {} sturm matrix <1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0, 0> {} }}\n", pad,
                         povNumber(form.major), povNumber(form.minor), modifiers);
      return;
    case QuarticForm::Kind::General: break;
  }
  std::string coefficients;
  for (double c : povQuarticOrder(shape.f)) fmt::format_to(std::back_inserter(coefficients), "{}{}", coefficients.empty() ? "" : ", ",
                                                      povNumber(c));
  out += fmt::format("{}quartic {{ <{}> sturm{} {} }}\n", pad, coefficients, bounded, modifiers);
}

// Spheres of `radius` at the points joined by cylinders: exactly the union of
// capsules Lattice builds (render/shapes/polyline_shape.hpp), POV-Ray's cylinders being capped.
void PovObjectWriter::tube(std::string& out, const std::vector<Vec3d>& points, double radius,
                           const std::string& modifiers, int depth) {
  const std::string pad = indent(depth), r = povNumber(radius);
  const bool single = points.size() == 1 || (points.size() == 2 && points[0] == points[1]);
  if (single) {
    out += fmt::format("{}sphere {{ {}, {} {} }}\n", pad, povVector(points[0]), r, modifiers);
    return;
  }
  if (options_.sphereSweep) {
    out += fmt::format("{}sphere_sweep {{ linear_spline {}", pad, points.size());
    for (const Vec3d& p : points) out += fmt::format(", {}, {}", povVector(p), r);
    out += fmt::format(" {} }}\n", modifiers);
    return;
  }
  out += fmt::format("{}union {{\n", pad);
  for (const Vec3d& p : points) out += fmt::format("{}  sphere {{ {}, {} }}\n", pad, povVector(p), r);
  for (std::size_t i = 1; i < points.size(); ++i)
    out += fmt::format("{}  cylinder {{ {}, {}, {} }}\n", pad, povVector(points[i - 1]), povVector(points[i]), r);
  out += fmt::format("{}  {}\n{}}}\n", pad, modifiers, pad);
}

const std::string& PovObjectWriter::latticeName(const LatticeShape& lattice, MaterialId material,
                                                const std::string& where) {
  if (!lattice.object)
    throw Error(ErrorKind::Internal, fmt::format("{}: lattice '{}' without its object", where, lattice.name));
  auto [it, added] = lattices_.try_emplace({lattice.object, material});
  if (!added) return it->second;
  it->second = fmt::format("Lattice{}", lattices_.size() - 1);
  std::string body;
  node(body, *lattice.object, material, 1);
  declarations_ += fmt::format("// lattice '{}' ({}) as its exact object, {}\n#declare {} = union {{\n{}}}\n\n",
                               lattice.name, where, povMaterialName(material), it->second, body);
  return it->second;
}

}  // namespace lattice::exporter
