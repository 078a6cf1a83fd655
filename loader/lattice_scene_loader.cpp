#include "loader/lattice_scene_loader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <tuple>
#include <type_traits>
#include <typeindex>

#include <glm/gtc/matrix_transform.hpp>

#include "lht/leaf/baked_lattice.hpp"
#include "lht/leaf/baked_lattice_union.hpp"
#include "loader/canonical_toml.hpp"
#include "lht/leaf/lattice_leaf.hpp"
#include "lht/raster/lattice_object.hpp"
#include "loader/lattice_tables.hpp"
#include "render/scene/instance_node.hpp"
#include "loader/scene_loader.hpp"
#include "foundation/error.hpp"
#include "foundation/threads.hpp"

namespace lattice::lht {

namespace {

// Fewer placements than this are computed in the caller: starting a thread
// would cost more than they do (a scatter has thousands).
constexpr std::size_t kParallelPlacements = 512;

// What one load defines, shared by the parsers of that load's format.
struct LatticeLoad {
  std::map<std::string, LatticeDefinitionPtr> byName;
  std::vector<LatticeDefinitionPtr> inOrder;
  std::shared_ptr<const LatticeTables> tables;
};

// `instanced`: the leaf stands for many placements of one object (a scatter),
// so the full ray trace builds that object once in object space and places it
// by instance nodes (render/scene/instance_node.hpp) instead of one world-space copy
// per placement.
class LatticeLeafDesc final : public LeafTemplate<LatticeLeafDesc> {
 public:
  LatticeLeafDesc(LatticeDefinitionPtr definition, std::shared_ptr<const LatticeTables> tables, bool instanced = false)
      : definition_(std::move(definition)), tables_(std::move(tables)), instanced_(instanced) {}

  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId material, const BuildOptions& options) const {
    // The full ray trace swaps the lattice for the object it was rasterized from.
    if (options.fullRayTrace) {
      if constexpr (std::is_floating_point_v<T>)
        if (instanced_)
          return makeInstance<T>(sharedObject<T>(material, options), toWorld, placedBounds(definition_->object, toWorld));
      return buildPrimitive<T>(definition_->object, toWorld, options, material);
    }
    return makeLatticeLeaf<T>(tables_->table(definition_), toWorld, material,
                              options.latticeShadows && definition_->shadows, tables_->lookupStats(definition_),
                              definition_->lookupUnder(tables_->settings()));
  }
  Bounds<double> objectBounds() const override { return definition_->objectBounds(); }
  std::string describe() const override { return fmt::format("lattice '{}'", definition_->name); }
  // Baked with its table built here (or read from its cache), for the firmware.
  std::string bake(SceneBaker& baker) const override {
    return bakeLatticeLeaf(baker, *tables_->table(definition_), definition_->shadows, definition_->name,
                           definition_->objectBounds());
  }
  // A scatter's instances as constant data (lht/leaf/baked_lattice_union.hpp),
  // when they are looked up the thesis's way (the firmware's).
  std::string bakeUnion(SceneBaker& baker, const NodeDesc& unionNode, const Mat4d& parentToWorld,
                        MaterialId inherited) const override {
    if (definition_->lookupUnder(tables_->settings()) != LatticeLookup::Thesis) return {};
    return bakeLatticeUnion(baker, definition_->name, unionNode, parentToWorld, inherited);
  }

  std::optional<LeafShape> shape() const override {
    return LatticeShape{&definition_->object, definition_->name, definition_->shadows};
  }

  const LatticeDefinitionPtr& definition() const { return definition_; }
  bool instanced() const { return instanced_; }

 private:
  // The object in its own space, built on first use for each arithmetic,
  // material and build option and shared by every instance from then on.
  template <typename T>
  SharedPrimitive<T> sharedObject(MaterialId material, const BuildOptions& options) const {
    const auto key = std::make_tuple(std::type_index(typeid(T)), material, options.latticeShadows);
    std::lock_guard lock(objectsMutex_);
    std::shared_ptr<const void>& slot = objects_[key];
    if (!slot) slot = SharedPrimitive<T>(buildPrimitive<T>(definition_->object, Mat4d(1.0), options, material));
    return std::static_pointer_cast<const Primitive<T>>(slot);
  }

  LatticeDefinitionPtr definition_;
  std::shared_ptr<const LatticeTables> tables_;
  bool instanced_;
  mutable Mutex objectsMutex_;
  mutable std::map<std::tuple<std::type_index, MaterialId, bool>, std::shared_ptr<const void>> objects_;
};

LatticeDefinitionPtr findDefinition(const toml::table& table, ParseContext& context, const LatticeLoad& load) {
  const auto name = context.string(table, "lattice");
  if (!name) context.fail(table, "a lattice object needs `lattice = \"NAME\"` naming a [[lattices]] entry");
  const auto& known = load.byName;
  const auto it = known.find(*name);
  if (it == known.end()) {
    std::string names;
    for (const auto& [n, d] : known) names += (names.empty() ? "" : ", ") + n;
    context.fail(*table.get("lattice"), fmt::format("no lattice named '{}' is defined in [[lattices]] (defined: {})",
                                                    *name, names.empty() ? "none" : names));
  }
  return it->second;
}

void parseLatticeSection(const toml::node& section, ParseContext& context, LatticeLoad& load) {
  const toml::array* list = section.as_array();
  if (!list) context.fail(section, "[[lattices]] must be an array of tables (write `[[lattices]]`)");
  for (const toml::node& entry : *list) {
    const toml::table* table = entry.as_table();
    if (!table) context.fail(entry, "each [[lattices]] entry must be a table");
    context.checkKeys(*table, {"name", "spacing", "oversample", "cache", "object", "shadows", "precision", "form",
                               "lookup"});
    auto def = std::make_shared<LatticeDefinition>();
    const auto name = context.string(*table, "name");
    if (!name || name->empty()) context.fail(*table, "a [[lattices]] entry needs a non-empty `name`");
    def->name = *name;
    def->origin = context.where(*table);
    def->lambda = context.positiveNumber(*table, "spacing");
    def->oversample = context.number(*table, "oversample").value_or(1.0);
    if (!(def->oversample >= 1.0 && def->oversample <= 255.0))
      context.fail(*table->get("oversample"), "`oversample` (f_lat) must be between 1 and 255");
    def->shadows = context.boolean(*table, "shadows").value_or(true);
    if (const auto precision = context.string(*table, "precision")) {
      const auto parsed = lhtPrecisionFromName(*precision);
      if (!parsed)
        context.fail(*table->get("precision"), fmt::format("unknown LHT entry `precision` '{}'; use one of {}",
                                                           *precision, lhtPrecisionChoices()));
      def->precision = *parsed;
    }
    if (const auto form = context.string(*table, "form")) {
      const auto parsed = lhtFormFromName(*form);
      if (!parsed)
        context.fail(*table->get("form"),
                     fmt::format("unknown LHT `form` '{}'; use one of {}", *form, lhtFormChoices()));
      def->form = *parsed;
    }
    if (const auto lookup = context.string(*table, "lookup")) {
      const auto parsed = latticeLookupFromName(*lookup);
      if (!parsed)
        context.fail(*table->get("lookup"),
                     fmt::format("unknown lattice `lookup` '{}'; use one of {}", *lookup, latticeLookupChoices()));
      def->lookup = *parsed;
    }
    if (const auto cache = context.string(*table, "cache")) {
      std::filesystem::path path(*cache);
      def->cache = path.is_absolute() ? path : context.file().parent_path() / path;
    }
    const toml::node* object = table->get("object");
    if (!object || !object->is_table())
      context.fail(*table, "a [[lattices]] entry needs `object = { type = ..., ... }`, the solid to rasterize");
    def->object = context.parseNode(*object);
    def->objectText = canonicalToml(*object);
    if (load.byName.count(def->name))
      context.fail(*table->get("name"), fmt::format("lattice '{}' is defined twice", def->name));
    load.byName[def->name] = def;
    load.inOrder.push_back(def);
  }
}

NodeDesc parseLatticeNode(const toml::table& table, ParseContext& context, const LatticeLoad& load) {
  context.checkKeys(table, {"lattice"}, true);
  return NodeDesc::makeLeaf(std::make_shared<LatticeLeafDesc>(findDefinition(table, context, load), load.tables),
                            context.where(table));
}

// The rotation taking +z to `normal`.
Mat4d alignZ(const Vec3d& normal) {
  const Vec3d w = glm::normalize(normal);
  const Vec3d helper = std::abs(w.x) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
  const Vec3d u = glm::normalize(glm::cross(helper, w));
  const Vec3d v = glm::cross(w, u);
  Mat4d m(1.0);
  m[0] = glm::dvec4(u, 0.0);
  m[1] = glm::dvec4(v, 0.0);
  m[2] = glm::dvec4(w, 0.0);
  return m;
}

NodeDesc parseScatterNode(const toml::table& table, ParseContext& context, const LatticeLoad& load) {
  context.checkKeys(table, {"lattice", "count", "radius", "seed"}, true);
  const LatticeDefinitionPtr def = findDefinition(table, context, load);
  const long long count = context.integer(table, "count").value_or(0);
  if (count < 1 || count > kMaxScatterCount)
    context.fail(table, fmt::format("`count` must be an integer between 1 and {} (how many instances to scatter; "
                                    "the limit is kMaxScatterCount, docs/limits.md)",
                                    kMaxScatterCount));
  const double radius = context.positiveNumber(table, "radius");
  const auto seed = static_cast<std::uint64_t>(context.integer(table, "seed").value_or(1));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> twist(0.0, 2.0 * std::numbers::pi);
  const LeafDescPtr leaf = std::make_shared<LatticeLeafDesc>(def, load.tables, /*instanced=*/true);
  const auto n = static_cast<std::size_t>(count);
  // The twists drawn in order from the one stream, the points of the
  // sphere, and the instances, then their transforms (each its own) on the
  // set-up's threads: the same matrices at every thread count.
  std::vector<double> twists(n);
  for (double& angle : twists) angle = twist(random);
  const std::vector<Vec3d> points = fibonacciSphere(static_cast<int>(count));
  std::vector<NodeDesc> instances(n, NodeDesc::makeLeaf(leaf));  // the union's origin is theirs (NodeDesc::origin)
  const auto place = [&](std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
      const Mat4d spin = glm::rotate(Mat4d(1.0), twists[i], Vec3d(0, 0, 1));
      instances[i].transform = glm::translate(Mat4d(1.0), points[i] * radius) * alignZ(points[i]) * spin;
    }
  };
  const unsigned threads = load.tables->settings().threads > 0 ? load.tables->settings().threads : hardwareThreads();
  const unsigned workers = n >= kParallelPlacements ? threads : 1;
  // Contiguous shares: the work makes no allocation (a worker thread's own
  // allocator arena would stay resident) and cannot fail.
  runWorkers(workers, [&](unsigned w) { place(n * w / workers, n * (w + 1) / workers); }, [] {});
  return NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(instances), context.where(table));
}

}  // namespace

std::vector<Vec3d> fibonacciSphere(int count) {
  std::vector<Vec3d> points;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double y = 1.0 - 2.0 * (i + 0.5) / count;  // equal-area bands
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = golden * i;
    points.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
  }
  return points;
}

namespace {

// The built-in format plus the lattice section and types, parsing into `load`.
SceneFormat latticeFormat(const std::shared_ptr<LatticeLoad>& load) {
  SceneFormat format = builtinSceneFormat();
  format.addSection("lattices", [load](const toml::node& section, ParseContext& context) {
    parseLatticeSection(section, context, *load);
  });
  format.addNodeType(std::string(LatticeShape::kName), [load](const toml::table& table, ParseContext& context) {
    return parseLatticeNode(table, context, *load);
  });
  format.addNodeType("lattice_scatter", [load](const toml::table& table, ParseContext& context) {
    return parseScatterNode(table, context, *load);
  });
  return format;
}

template <typename Load>
SceneWithLattices loadWithLattices(const TableSettings& tables, Load load) {
  auto state = std::make_shared<LatticeLoad>();
  state->tables = std::make_shared<const LatticeTables>(tables);
  SceneWithLattices found;
  found.scene = load(latticeFormat(state));
  found.lattices = std::move(state->inOrder);
  found.tables = tables;
  return found;
}

// A copy of the tree whose lattice leaves use `tables`; a leaf shared by
// many instances stays shared.
NodeDesc rebind(const NodeDesc& node, const std::shared_ptr<const LatticeTables>& tables,
                std::map<const LeafDesc*, LeafDescPtr>& rebound) {
  NodeDesc copy;
  copy.kind = node.kind;
  copy.transform = node.transform;
  copy.material = node.material;
  copy.origin = node.origin;
  copy.leaf = node.leaf;
  if (const auto* lattice = dynamic_cast<const LatticeLeafDesc*>(node.leaf.get())) {
    LeafDescPtr& leaf = rebound[node.leaf.get()];
    if (!leaf) leaf = std::make_shared<LatticeLeafDesc>(lattice->definition(), tables, lattice->instanced());
    copy.leaf = leaf;
  }
  copy.children.reserve(node.children.size());
  for (const NodeDesc& child : node.children) copy.children.push_back(rebind(child, tables, rebound));
  return copy;
}

}  // namespace

SceneWithLattices loadSceneWithLattices(const std::filesystem::path& sceneFile, const TableSettings& tables) {
  return loadWithLattices(tables, [&](const SceneFormat& format) { return loadScene(sceneFile, format); });
}

SceneWithLattices parseSceneWithLattices(std::string_view text, const std::filesystem::path& fileName,
                                         const TableSettings& tables) {
  return loadWithLattices(tables, [&](const SceneFormat& format) { return parseScene(text, fileName, format); });
}

SceneWithLattices withTableSettings(const SceneWithLattices& loaded, const TableSettings& tables) {
  SceneWithLattices bound = loaded;
  std::map<const LeafDesc*, LeafDescPtr> rebound;
  bound.scene.root = rebind(loaded.scene.root, std::make_shared<const LatticeTables>(tables), rebound);
  bound.tables = tables;
  return bound;
}

}  // namespace lattice::lht
