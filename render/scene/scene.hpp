#pragma once
// The scene description: what a scene file says, in double precision, before
// any ray is traced. The renderer builds an intersectable tree for its scalar
// type T from it (buildPrimitive<T>), once.
//
// Objects form a CSG tree of NodeDesc (thesis sec. 3.1, fig. 4). Any node may
// carry a local transform and a material; building the tree propagates both
// downwards, so only leaves end up holding a transform (object -> world) and a
// material, as the thesis keeps them. A leaf is anything implementing
// LeafDesc: quartic shapes (render/), lattices (lht/), ...
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "foundation/bounds.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/light.hpp"
#include "render/scene/material.hpp"
#include "render/shapes/leaf_shape.hpp"
#include "render/shapes/primitive.hpp"
#include "foundation/vec.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

class SceneBaker;

// How leaves are built; set by the renderer's caller.
struct BuildOptions {
  // Replace every lattice by the exact object it was rasterized from (the
  // reference image a lattice render is compared with).
  bool fullRayTrace = false;
  // Lattices cast shadows on each other and on themselves (thesis plate 4);
  // off, they behave like a particle system (plate 3).
  bool latticeShadows = true;
  // Threads the build may use (a render job gives the render's count): a
  // set operation of many operands builds them, and a union its BVH, on this
  // many (render/scene/scene.cpp). The tree is the same at every count.
  unsigned threads = 1;
};

// The result slot of one LeafDesc::build, for the arithmetic T asked for.
template <typename T>
struct BuiltLeaf {
  PrimitivePtr<T> primitive;
};

// A leaf of the CSG tree: something that can build an intersector for itself
// in every arithmetic (foundation/arithmetics.hpp). Leaves derive from
// LeafTemplate below and write their build once, as a template.
class LeafDesc {
 public:
  virtual ~LeafDesc() = default;
  template <typename T>
  PrimitivePtr<T> build(const Mat4d& objectToWorld, MaterialId material, const BuildOptions& options) const {
    ArithmeticVariant<BuiltLeaf> out{std::in_place_type<BuiltLeaf<T>>};
    buildInto(objectToWorld, material, options, out);
    return std::move(std::get<BuiltLeaf<T>>(out).primitive);
  }
  // The solid's box in its own (object) coordinates; may be infinite.
  virtual Bounds<double> objectBounds() const = 0;
  // A short human-readable name for messages ("sphere", "lattice 'hair'").
  virtual std::string describe() const = 0;
  // A C++ expression of type LeafDescPtr that rebuilds this leaf in a baked
  // scene (render/scene/scene_baker.hpp, docs/firmware.md). A build that only
  // renders scenes baked elsewhere (the firmware defines LATTICE_NO_BAKER)
  // leaves the leaves' overrides out, so no baker is linked. The default refuses
  // with lattice::Error(Usage) naming the leaf.
  virtual std::string bake(SceneBaker& baker) const;
  // A C++ expression of type LeafDescPtr standing for the whole of
  // `unionNode`, a union every child of which is a leaf of this very
  // description (a scatter's instances), placed by parentToWorld with the
  // material `inherited`: the instances as constant data instead of a node
  // each. Empty (the default): the union is baked node by node.
  virtual std::string bakeUnion(SceneBaker& baker, const NodeDesc& unionNode, const Mat4d& parentToWorld,
                                MaterialId inherited) const;
  // What it is made of (render/shapes/leaf_shape.hpp), for writing the scene
  // for another renderer, covers and bounds; nothing for a leaf that does
  // not say (a baked lattice).
  virtual std::optional<LeafShape> shape() const { return std::nullopt; }

 protected:
  // Fills the slot `out` holds (its alternative names the arithmetic).
  virtual void buildInto(const Mat4d& objectToWorld, MaterialId material, const BuildOptions& options,
                         ArithmeticVariant<BuiltLeaf>& out) const = 0;
};

// A leaf written once as a template: Derived provides
//   template <typename T>
//   PrimitivePtr<T> buildAs(const Mat4d& objectToWorld, MaterialId, const BuildOptions&) const;
// and this class dispatches every arithmetic of the list to it, so adding an
// arithmetic touches no leaf.
//
// A build that renders only in fixed point (the firmware defines
// LATTICE_FIXED_POINT_ONLY) instantiates buildAs for Fixed32 alone: the float
// and double leaves, CSG nodes and BVHs it would never call are then not
// linked (docs/firmware.md, "Memory: before and after"); asking throws.
[[noreturn]] void throwArithmeticLeftOut(std::string_view arithmetic);

template <typename Derived>
class LeafTemplate : public LeafDesc {
 protected:
  void buildInto(const Mat4d& objectToWorld, MaterialId material, const BuildOptions& options,
                 ArithmeticVariant<BuiltLeaf>& out) const final {
    std::visit(
        [&]<typename T>(BuiltLeaf<T>& slot) {
#ifdef LATTICE_FIXED_POINT_ONLY
          if constexpr (!std::is_same_v<T, Fixed32>) throwArithmeticLeftOut(arithmeticName<T>());
          else
#endif
            slot.primitive = static_cast<const Derived&>(*this).template buildAs<T>(objectToWorld, material, options);
        },
        out);
  }
};

using LeafDescPtr = std::shared_ptr<const LeafDesc>;

struct NodeDesc {
  enum class Kind { Leaf, Union, Intersection, Difference };
  Kind kind = Kind::Union;
  // Kind::Leaf only.
  LeafDescPtr leaf;
  // Set operations: the operands. Difference is children[0] minus the union of
  // the rest. An empty union is empty space.
  std::vector<NodeDesc> children;
  // This node's coordinates -> its parent's coordinates.
  Mat4d transform{1.0};
  // Unset: inherited from the nearest ancestor that has one (the scene's
  // "default" material, id 0, at the root).
  std::optional<MaterialId> material;
  // Where the node was defined ("scene.toml:12:3"), for messages; empty:
  // where its parent was (a scatter's instances share their union's, held
  // once instead of in each of thousands of nodes).
  std::string origin;

  static NodeDesc makeLeaf(LeafDescPtr leafDesc, std::string where = {});
  static NodeDesc makeOperation(Kind kind, std::vector<NodeDesc> operands, std::string where = {});
};

struct SceneOptions {
  Vec3d ambient{0.2};         // I_amb per channel
  double attenuationK = 1.0;  // K in 1 / (D_i + K)
  Vec3d background{0.0};      // colour of rays that hit nothing (linear, 0..1)
  int width = 256;            // default image size (the CLI may override)
  int height = 256;
  bool shadows = true;        // trace shadow rays (off: every light is visible)
};

struct SceneDesc {
  std::filesystem::path source;  // the file it came from (empty when built in code)
  CameraDesc camera;
  std::vector<PointLight<double>> lights;
  // Index = MaterialId. Entry 0 is always the "default" material.
  std::vector<NamedMaterial> materials{NamedMaterial{"default", Material<double>{}}};
  SceneOptions options;
  NodeDesc root;  // the union of the scene's top-level objects

  // MaterialId of a name, if defined.
  std::optional<MaterialId> findMaterial(const std::string& name) const;
  // Adds (or replaces) a named material and returns its id.
  MaterialId addMaterial(const std::string& name, const Material<double>& material);
};

// Builds the intersector of a subtree for T. The node's transform is applied
// after parentToWorld (world <- parent <- node), and leaves without a material
// get `inherited`. Throws lattice::Error(Input) when a leaf cannot be built.
template <typename T>
PrimitivePtr<T> buildPrimitive(const NodeDesc& node, const Mat4d& parentToWorld, const BuildOptions& options,
                               MaterialId inherited = 0);
// The same, releasing the tree as it goes: each set operation's operand
// descriptions are freed once its operands are built, before the operation
// builds its BVH over them, so a scatter's descriptions and the BVH's build
// never take memory at once (docs/memory.md). `node` is left with no
// operands.
template <typename T>
PrimitivePtr<T> buildPrimitive(NodeDesc&& node, const Mat4d& parentToWorld, const BuildOptions& options,
                               MaterialId inherited = 0);

#define LATTICE_DECLARE(T)                                                                                         \
  extern template PrimitivePtr<T> buildPrimitive<T>(const NodeDesc&, const Mat4d&, const BuildOptions&, MaterialId); \
  extern template PrimitivePtr<T> buildPrimitive<T>(NodeDesc&&, const Mat4d&, const BuildOptions&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
