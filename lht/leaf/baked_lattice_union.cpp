#include "lht/leaf/baked_lattice_union.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"
#include "lht/leaf/baked_lattice.hpp"
#include "lht/leaf/thesis_lattice_leaf.hpp"
#include "render/accel/wide_bvh.hpp"
#include "render/scene/scene_baker.hpp"
#include "render/shapes/union_core.hpp"

namespace lattice::lht {
namespace {

using detail::ThesisLatticeLeaf;

// The union's children are all finite and in the tree, and its box is theirs
// uncut, so UnionNode's own box test would decide nothing: only an empty
// union is outside.
class BakedLatticeUnion final : public UnionCore<Fixed32, BakedLatticeUnion, Primitive<Fixed32>> {
 public:
  explicit BakedLatticeUnion(const BakedLatticeUnionData& data)
      : table_(data.table),
        lookup_(*table_),
        placements_(data.placements),
        bvh_(Bvh<Fixed32>::view(data.nodes, data.items, data.depth)),
        bounds_(data.bounds) {}

  const Bounds<Fixed32>& bounds() const override { return bounds_; }

  // What UnionCore asks.
  bool outsideBox(const Ray<Fixed32>&, Fixed32, Fixed32) const { return bounds_.empty(); }
  std::size_t unboundedCount() const { return 0; }
  template <typename F>
  decltype(auto) withUnbounded(std::size_t k, F f) const {  // never called: no child is unbounded
    return withItem(static_cast<std::uint32_t>(k), f);
  }
  const Bvh<Fixed32>& bvh() const { return bvh_; }
  template <typename F>
  decltype(auto) withItem(std::uint32_t item, F f) const {
    const ThesisLatticeLeaf<Fixed32> leaf(table_->box, lookup_, placements_[item]);
    return f(leaf);
  }

 private:
  std::shared_ptr<const LhtFile> table_;
  LhtLookup lookup_;
  std::span<const LatticePlacement<Fixed32>> placements_;
  Bvh<Fixed32> bvh_;
  Bounds<Fixed32> bounds_;
};

class BakedLatticeUnionDesc final : public LeafTemplate<BakedLatticeUnionDesc> {
 public:
  explicit BakedLatticeUnionDesc(BakedLatticeUnionData data) : data_(std::move(data)) {}

  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId, const BuildOptions& options) const {
    if constexpr (!std::is_same_v<T, Fixed32>) {
      throw Error(ErrorKind::Usage, fmt::format("{} is baked in fixed point: render it with --arith fixed",
                                                describe()));
    } else {
      if (options.fullRayTrace)
        throw Error(ErrorKind::Usage, fmt::format("{} is baked without its object: no full ray trace", describe()));
      if (toWorld != data_.unionToWorld || !options.latticeShadows)
        throw Error(ErrorKind::Internal, fmt::format("{} is placed or lit otherwise than it was baked for: bake "
                                                     "the scene again (lattice bake)",
                                                     describe()));
      return makeBakedLatticeUnion(data_);
    }
  }
  Bounds<double> objectBounds() const override {
    return {Vec3d(data_.bounds.lo), Vec3d(data_.bounds.hi)};
  }
  std::string describe() const override {
    return fmt::format("baked union of {} instances of lattice '{}'", data_.placements.size(), data_.name);
  }

 private:
  BakedLatticeUnionData data_;
};

// Literals of a baked file: V a vector of raw Fixed32 values, B a box (the
// helpers bakeLatticeUnion defines once in the generated file).
std::string vecLiteral(const Vec3<Fixed32>& v) {
  return fmt::format("V({}, {}, {})", v.x.raw(), v.y.raw(), v.z.raw());
}
std::string boxLiteral(const Bounds<Fixed32>& b) { return fmt::format("B({}, {})", vecLiteral(b.lo), vecLiteral(b.hi)); }

}  // namespace

PrimitivePtr<Fixed32> makeBakedLatticeUnion(const BakedLatticeUnionData& data) {
  if (!data.table || data.placements.empty() || data.nodes.empty())
    throw Error(ErrorKind::Internal, "baked lattice union without a table, placements or tree");
  return std::make_unique<BakedLatticeUnion>(data);
}

LeafDescPtr makeBakedLatticeUnionDesc(BakedLatticeUnionData data) {
  return std::make_shared<BakedLatticeUnionDesc>(std::move(data));
}

BakedLatticeUnionData LatticeUnionArrays::view(std::string name) const {
  return {table, placements, bvh.nodes(), bvh.items(), bvh.depth(), bounds, unionToWorld, std::move(name)};
}

std::optional<LatticeUnionArrays> collectLatticeUnion(const NodeDesc& unionNode, const Mat4d& parentToWorld,
                                                      MaterialId inherited) {
  if (unionNode.kind != NodeDesc::Kind::Union || unionNode.children.size() < 2) return std::nullopt;
  // What the firmware's renderer builds (RenderSettings' default options):
  // each child exactly as buildPrimitive makes it, then its placement.
  LatticeUnionArrays out;
  out.unionToWorld = parentToWorld * unionNode.transform;
  const MaterialId material = unionNode.material.value_or(inherited);
  const BuildOptions options;
  std::vector<Bounds<Fixed32>> boxes;
  for (const NodeDesc& child : unionNode.children) {
    const PrimitivePtr<Fixed32> built = buildPrimitive<Fixed32>(child, out.unionToWorld, options, material);
    const auto* leaf = dynamic_cast<const ThesisLatticeLeaf<Fixed32>*>(built.get());
    if (!leaf || leaf->countsLookups()) return std::nullopt;
    if (!out.table) out.table = leaf->table();
    if (leaf->table() != out.table) return std::nullopt;
    const Bounds<Fixed32>& b = leaf->bounds();
    if (b.empty() || !b.isFinite()) return std::nullopt;  // UnionNode would keep it out of the tree
    out.placements.push_back(leaf->placement());
    boxes.push_back(b);
    out.bounds.extend(b);
  }
  out.bvh = Bvh<Fixed32>(boxes);  // as UnionNode builds it: every child, in order
  return out;
}

std::string bakeLatticeUnion(SceneBaker& baker, const std::string& name, const NodeDesc& unionNode,
                             const Mat4d& parentToWorld, MaterialId inherited) {
  const std::optional<LatticeUnionArrays> arrays = collectLatticeUnion(unionNode, parentToWorld, inherited);
  if (!arrays) return {};
  const std::vector<LatticePlacement<Fixed32>>& placements = arrays->placements;
  const Bvh<Fixed32>& bvh = arrays->bvh;
  const Bounds<Fixed32>& bounds = arrays->bounds;
  const Mat4d& toWorld = arrays->unionToWorld;
  baker.include("lht/leaf/baked_lattice_union.hpp");
  std::string text;
  if (baker.defineOnce("fixed-literals"))
    text += "constexpr lattice::Fixed32 R(long long raw) { return lattice::Fixed32::fromRaw(raw); }\n"
            "constexpr lattice::Vec3<lattice::Fixed32> V(long long x, long long y, long long z) {\n"
            "  return lattice::Vec3<lattice::Fixed32>(R(x), R(y), R(z));\n}\n"
            "constexpr lattice::Bounds<lattice::Fixed32> B(lattice::Vec3<lattice::Fixed32> lo, "
            "lattice::Vec3<lattice::Fixed32> hi) {\n  return lattice::Bounds<lattice::Fixed32>{lo, hi};\n}\n";
  text += fmt::format("// lattice '{}': {} instances and their BVH ({} nodes), as constant data\n", name,
                      placements.size(), bvh.nodes().size());
  const std::string placementsName = baker.freshName("kPlacements");
  const std::string nodesName = baker.freshName("kBvhNodes");
  const std::string itemsName = baker.freshName("kBvhItems");
  text += fmt::format("constexpr lattice::lht::LatticePlacement<lattice::Fixed32> {}[] = {{\n", placementsName);
  for (const LatticePlacement<Fixed32>& p : placements) {
    const auto& a = p.worldToLattice;
    const auto& m = p.normalMap;
    text += fmt::format(
        "  {{lattice::lht::LatticeAffine<lattice::Fixed32>({}, {}, {}, {}),\n   lattice::Mat3<lattice::Fixed32>({}, {}, "
        "{}),\n   {}, {}u, {}}},\n",
        vecLiteral(a.column(0)), vecLiteral(a.column(1)), vecLiteral(a.column(2)), vecLiteral(a.column(3)),
        vecLiteral(m[0]), vecLiteral(m[1]), vecLiteral(m[2]), boxLiteral(p.bounds), p.material,
        p.castsShadows ? "true" : "false");
  }
  text += "};\n";
  text += fmt::format("constexpr lattice::Bvh<lattice::Fixed32>::Node {}[] = {{\n", nodesName);
  for (const auto& n : bvh.nodes()) text += fmt::format("  {{{}, {}u, {}u}},\n", boxLiteral(n.box), n.first, n.count);
  text += "};\n";
  text += fmt::format("constexpr std::uint32_t {}[] = {{", itemsName);
  for (std::size_t i = 0; i < bvh.items().size(); ++i)
    text += fmt::format("{}{}u,", i % 16 == 0 ? "\n  " : "", bvh.items()[i]);
  text += "\n};\n";
  baker.constantData(std::move(text), placements.size() * sizeof(LatticePlacement<Fixed32>) +
                                          bvh.nodes().size() * sizeof(Bvh<Fixed32>::Node) +
                                          bvh.items().size() * sizeof(std::uint32_t));
  return fmt::format(
      "lattice::lht::makeBakedLatticeUnionDesc(lattice::lht::BakedLatticeUnionData{{{}, {}, {}, {}, {}, {}, {}, \"{}\"}})",
      bakedTableExpression(baker, *arrays->table, name), placementsName, nodesName, itemsName, bvh.depth(), boxLiteral(bounds),
      baker.mat4(toWorld), name);
}

}  // namespace lattice::lht
