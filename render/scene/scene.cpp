#include "render/scene/scene.hpp"

#include <fmt/format.h>

#include "render/shapes/csg.hpp"
#include "foundation/transform_condition.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"
#include "foundation/ordered_parallel_for.hpp"

namespace lattice {

std::string LeafDesc::bake(SceneBaker&) const {
  throw Error(ErrorKind::Usage, fmt::format("{} cannot be baked for the firmware (docs/firmware.md lists the leaves "
                                            "a baked scene can hold)", describe()));
}

void throwArithmeticLeftOut(std::string_view arithmetic) {
  throw Error(ErrorKind::Usage, fmt::format("this build renders in fixed point only, not in {} (it is built with "
                                            "LATTICE_FIXED_POINT_ONLY, as the firmware is): use --arith fixed",
                                            arithmetic));
}

std::string LeafDesc::bakeUnion(SceneBaker&, const NodeDesc&, const Mat4d&, MaterialId) const { return {}; }

NodeDesc NodeDesc::makeLeaf(LeafDescPtr leafDesc, std::string where) {
  NodeDesc n;
  n.kind = Kind::Leaf;
  n.leaf = std::move(leafDesc);
  n.origin = std::move(where);
  return n;
}

NodeDesc NodeDesc::makeOperation(Kind kind, std::vector<NodeDesc> operands, std::string where) {
  NodeDesc n;
  n.kind = kind;
  n.children = std::move(operands);
  n.origin = std::move(where);
  return n;
}

std::optional<MaterialId> SceneDesc::findMaterial(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<MaterialId>(i);
  return std::nullopt;
}

MaterialId SceneDesc::addMaterial(const std::string& name, const Material<double>& material) {
  if (auto id = findMaterial(name)) {
    materials[*id].material = material;
    return *id;
  }
  materials.push_back({name, material});
  return static_cast<MaterialId>(materials.size() - 1);
}

namespace {

const std::string kUnplaced = "scene";  // the root's place when it has none

// Fewer operands than this are built in the caller: starting the threads
// would cost more than the builds (a scatter has thousands of operands).
constexpr std::size_t kParallelOperands = 256;

// Node: const NodeDesc (the tree is kept) or NodeDesc (each set operation's
// operand descriptions are released once its operands are built).
template <typename T, typename Node>
PrimitivePtr<T> buildNode(Node& node, const Mat4d& parentToWorld, const BuildOptions& options, MaterialId inherited,
                          const std::string& parentWhere) {
  // Fig. 4: transforms on inner nodes are pushed down, so each leaf gets the
  // full object -> world matrix and the set operations hold none.
  const Mat4d toWorld = parentToWorld * node.transform;
  const MaterialId material = node.material.value_or(inherited);
  const std::string& where = node.origin.empty() ? parentWhere : node.origin;
  if (node.kind == NodeDesc::Kind::Leaf) {
    if (!node.leaf) throw Error(ErrorKind::Internal, fmt::format("{}: leaf node without a leaf description", where));
    // Scene files are held to the limit of every arithmetic when loaded; an
    // arithmetic that follows less (float) refuses here, naming the object.
    const std::string problem = conditionProblemFor<T>(toWorld);
    if (!problem.empty()) throw Error(ErrorKind::Input, fmt::format("{}: {}", where, problem));
    PrimitivePtr<T> p;
    try {
      p = node.leaf->template build<T>(toWorld, material, options);
    } catch (const Error& e) {
      // Leaves report what is wrong but not where; name the object, unless
      // the message already names a place in the scene file.
      const std::string message = e.what();
      const std::string file = where.substr(0, where.find(':'));
      if (message.rfind(file + ":", 0) == 0) throw;
      throw Error(e.kind(), fmt::format("{}: {}", where, message));
    }
    if (!p) throw Error(ErrorKind::Internal, fmt::format("{}: {} built no primitive", where, node.leaf->describe()));
    return p;
  }
  if (node.children.empty())
    throw Error(ErrorKind::Input, fmt::format("{}: a set operation needs at least one child object", where));
  std::vector<PrimitivePtr<T>> children(node.children.size());
  const auto buildChild = [&](std::size_t i, const BuildOptions& childOptions) {
    children[i] = buildNode<T>(node.children[i], toWorld, childOptions, material, where);
  };
  if (kHasThreads && options.threads > 1 && children.size() >= kParallelOperands) {
    // The first operand in the caller: it builds what its siblings share (a
    // lattice's table, rasterized on every thread), the rest on every thread,
    // each below them serially. Each operand fills its own slot, so the tree
    // is the one the plain loop makes; errors too (ordered_parallel_for.hpp).
    BuildOptions serial = options;
    serial.threads = 1;
    buildChild(0, options);
    orderedParallelFor(children.size() - 1, options.threads, [&](std::size_t i) { buildChild(i + 1, serial); });
  } else {
    for (std::size_t i = 0; i < children.size(); ++i) buildChild(i, options);
  }
  if constexpr (!std::is_const_v<Node>) std::vector<NodeDesc>().swap(node.children);  // before the BVH's build
  // A set operation of one operand is that operand; skipping the node saves
  // a span merge per ray.
  if (children.size() == 1) return std::move(children.front());
  const CsgOp op = node.kind == NodeDesc::Kind::Union          ? CsgOp::Union
                   : node.kind == NodeDesc::Kind::Intersection ? CsgOp::Intersection
                                                               : CsgOp::Difference;
  return makeCsgNode<T>(op, std::move(children), options.threads);
}

}  // namespace

template <typename T>
PrimitivePtr<T> buildPrimitive(const NodeDesc& node, const Mat4d& parentToWorld, const BuildOptions& options,
                               MaterialId inherited) {
  return buildNode<T>(node, parentToWorld, options, inherited, kUnplaced);
}
template <typename T>
PrimitivePtr<T> buildPrimitive(NodeDesc&& node, const Mat4d& parentToWorld, const BuildOptions& options,
                               MaterialId inherited) {
  return buildNode<T>(node, parentToWorld, options, inherited, kUnplaced);
}

#define LATTICE_INSTANTIATE(T)                                                                            \
  template PrimitivePtr<T> buildPrimitive<T>(const NodeDesc&, const Mat4d&, const BuildOptions&, MaterialId); \
  template PrimitivePtr<T> buildPrimitive<T>(NodeDesc&&, const Mat4d&, const BuildOptions&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
