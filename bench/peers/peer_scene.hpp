#pragma once
// A scene loaded by our own loader (lht::loadSceneWithLattices) reduced to
// what the Embree peer traces: closed-form spheres and planes, tubes (spheres
// joined by cylinders of one radius: polylines and capsules, Embree's round
// linear curves), and lattice instances, each a transform of one shared
// exact object (the object the lattice was rasterized from).
//
// Method: walk the CSG tree multiplying transforms down (as buildPrimitive
// does); a leaf says what it is (LeafDesc::shape), a quartic's polynomial
// which closed form it is (exporter/quartic_forms.hpp). Only unions can be
// flattened, and spheres and tubes only under similarity transforms; anything
// else (intersection, difference, a torus or general quartic, a lattice that
// casts no shadows) is refused with lattice::Error naming the object's file
// and line, and bench/peers.sh reports that scene as not traced by Embree.
#include <optional>
#include <vector>

#include "render/scene/scene.hpp"

namespace lattice::peers {

struct PeerSphere {
  Vec3d centre;
  double radius = 0;
  std::optional<MaterialId> material;  // unset inside a lattice object: the instance's
};

struct PeerPlane {  // the solid normal . p < offset, |normal| = 1
  Vec3d normal;
  double offset = 0;
  MaterialId material = 0;
};

struct PeerTube {
  std::vector<Vec3d> points;
  double radius = 0;
  std::optional<MaterialId> material;
};

struct PeerObject {  // world parts, or a lattice's exact object in its own coordinates
  std::vector<PeerSphere> spheres;
  std::vector<PeerTube> tubes;
};

struct PeerInstance {
  std::size_t object = 0;  // index into PeerScene::shared
  Mat4d toWorld{1.0};
  MaterialId material = 0;
};

struct PeerScene {
  PeerObject world;
  std::vector<PeerPlane> planes;
  std::vector<PeerObject> shared;
  std::vector<PeerInstance> instances;
};

PeerScene flattenScene(const SceneDesc& scene);

}  // namespace lattice::peers
