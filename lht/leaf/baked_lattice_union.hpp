#pragma once
// A union of many placements of one lattice held as constant data (a baked
// scene's scatter, docs/firmware.md): the placements (lht/leaf/lattice_placement.hpp),
// the BVH's node and item arrays and the union's box are what the renderer
// would build from the scene at start-up, computed by `lattice bake` on the
// host and written as constexpr arrays, so the firmware keeps them in flash
// and builds nothing for them in RAM.
//
// Method: a ray is answered by render/shapes/union_core.hpp's walk, as the
// CSG union of the instance leaves is; each BVH item visited becomes a
// lattice leaf on the stack, made from its placement
// (lht/leaf/thesis_lattice_leaf.hpp), so every answer, and the picture, is
// the built tree's. Fixed point only (the firmware's arithmetic): other
// arithmetics refuse with lattice::Error(Usage).
//
// Tunables: none.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lht/file/lht_file.hpp"
#include "lht/leaf/lattice_placement.hpp"
#include "render/accel/bvh.hpp"
#include "render/scene/scene.hpp"

namespace lattice::lht {

// What a baked union of lattice instances is made of; the spans' arrays
// outlive it (constant data).
struct BakedLatticeUnionData {
  std::shared_ptr<const LhtFile> table;  // shared by every instance
  std::span<const LatticePlacement<Fixed32>> placements;  // BVH item n is placements[n]
  std::span<const Bvh<Fixed32>::Node> nodes;
  std::span<const std::uint32_t> items;
  int depth = 0;
  Bounds<Fixed32> bounds;  // the union of the placements' boxes
  Mat4d unionToWorld{1.0};  // the world map the bake assumed; the build checks it
  std::string name;         // the lattice's, for messages
};

// The union as a primitive (Fixed32).
PrimitivePtr<Fixed32> makeBakedLatticeUnion(const BakedLatticeUnionData& data);

// The same as a CSG leaf of a baked scene.
LeafDescPtr makeBakedLatticeUnionDesc(BakedLatticeUnionData data);

// What the renderer would build for `unionNode` (a union whose children are
// leaves of one lattice), placed by parentToWorld with the material
// `inherited`, as arrays: each child built as buildPrimitive<Fixed32> builds
// it, its placement, and the BVH the CSG union makes over their boxes.
// nullopt when a child does not build to a thesis-look-up lattice leaf, the
// leaves read different tables, a box is empty or infinite, or there are
// fewer than two children (the CSG union would then not keep them all in its
// tree).
struct LatticeUnionArrays {
  std::shared_ptr<const LhtFile> table;  // the one every child's leaf reads
  std::vector<LatticePlacement<Fixed32>> placements;
  Bvh<Fixed32> bvh;
  Bounds<Fixed32> bounds;
  Mat4d unionToWorld{1.0};
  // A view of these arrays (they must outlive it).
  BakedLatticeUnionData view(std::string name) const;
};
std::optional<LatticeUnionArrays> collectLatticeUnion(const NodeDesc& unionNode, const Mat4d& parentToWorld,
                                                      MaterialId inherited);

// `lattice bake`'s side: the C++ expression (render/scene/scene_baker.hpp) of
// a LeafDescPtr standing for `unionNode` (a union whose children are leaves
// of the lattice `name`), placed by parentToWorld with the material
// `inherited`; empty when collectLatticeUnion finds it cannot be baked this
// way, and the union is then baked node by node.
std::string bakeLatticeUnion(SceneBaker& baker, const std::string& name, const NodeDesc& unionNode,
                             const Mat4d& parentToWorld, MaterialId inherited);

}  // namespace lattice::lht
