#pragma once
// What a scene leaf is made of, told to code that writes the scene for
// another renderer (exporter/: POV-Ray files; bench/peers/: Embree). The
// tracer never asks: it builds intersectors through LeafDesc::build.
//
// Method: a leaf answers with the exact parameters it was built from, not
// with its intersector, so a writer can pick the peer's own closed forms
// (a quartic leaf's polynomial says whether it is a plane, a sphere, a
// quadric or a torus; exporter/quartic_forms.hpp). A lattice answers with the
// exact object it was rasterized from, shared by all its instances.
#include <string>
#include <utility>
#include <vector>

#include "render/shapes/quartic_presets.hpp"

namespace lattice {

struct NodeDesc;

struct LeafShape {
  enum class Kind {
    Opaque,    // nothing an exporter can write (a leaf type that does not say)
    Quartic,   // f < 0 within bounds: `quartic`
    Capsule,   // the segment (0,0,0)-(0,0,length) swept by a ball of `radius`
    Polyline,  // spheres of `radius` at `points` joined by cylinders
    Lattice,   // a lattice: `object` is its exact solid (object coordinates)
  };
  Kind kind = Kind::Opaque;
  QuarticShape quartic{};
  double radius = 0;
  double length = 0;
  std::vector<Vec3d> points;
  const NodeDesc* object = nullptr;  // Lattice: owned by the definition, which outlives the scene
  std::string name;                  // Lattice: the definition's name
  bool castsShadows = true;          // Lattice: false for `shadows = false` (thesis plate 3)

  static LeafShape ofQuartic(const QuarticShape& shape) {
    LeafShape s;
    s.kind = Kind::Quartic;
    s.quartic = shape;
    return s;
  }
  static LeafShape ofCapsule(double radius, double length) {
    LeafShape s;
    s.kind = Kind::Capsule;
    s.radius = radius;
    s.length = length;
    return s;
  }
  static LeafShape ofPolyline(std::vector<Vec3d> points, double radius) {
    LeafShape s;
    s.kind = Kind::Polyline;
    s.points = std::move(points);
    s.radius = radius;
    return s;
  }
};

}  // namespace lattice
