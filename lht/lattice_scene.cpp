#include "lht/lattice_scene.hpp"

#include <fmt/format.h>

#include <any>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "lht/canonical_toml.hpp"
#include "lht/lattice_leaf.hpp"
#include "lht/lattice_object.hpp"
#include "lht/polyline.hpp"
#include "render/scene_loader.hpp"
#include "foundation/error.hpp"

namespace lattice::lht {

namespace {

using DefinitionMap = std::map<std::string, LatticeDefinitionPtr>;
constexpr const char* kExtension = "lht";

// `lattice rasterize --scene` collects the definitions a load parses.
thread_local std::vector<LatticeDefinitionPtr>* capturedDefinitions = nullptr;

class LatticeLeafDesc final : public LeafDesc {
 public:
  explicit LatticeLeafDesc(LatticeDefinitionPtr definition) : definition_(std::move(definition)) {}

  PrimitivePtr<float> build(const Mat4d& toWorld, MaterialId m, const BuildOptions& o, float) const override {
    return buildFor<float>(toWorld, m, o);
  }
  PrimitivePtr<double> build(const Mat4d& toWorld, MaterialId m, const BuildOptions& o, double) const override {
    return buildFor<double>(toWorld, m, o);
  }
  PrimitivePtr<Fixed32> build(const Mat4d& toWorld, MaterialId m, const BuildOptions& o, Fixed32) const override {
    return buildFor<Fixed32>(toWorld, m, o);
  }
  Bounds<double> objectBounds() const override { return definition_->objectBounds(); }
  std::string describe() const override { return fmt::format("lattice '{}'", definition_->name); }

 private:
  template <typename T>
  PrimitivePtr<T> buildFor(const Mat4d& toWorld, MaterialId material, const BuildOptions& options) const {
    // The full ray trace swaps the lattice for the object it was rasterized from.
    if (options.fullRayTrace) return buildPrimitive<T>(definition_->object, toWorld, options, material);
    return makeLatticeLeaf<T>(definition_->table(), toWorld, material,
                              options.latticeShadows && definition_->shadows);
  }
  LatticeDefinitionPtr definition_;
};

DefinitionMap& definitions(ParseContext& context) {
  std::any& slot = context.extensions()[kExtension];
  if (!slot.has_value()) slot = DefinitionMap{};
  return *std::any_cast<DefinitionMap>(&slot);
}

LatticeDefinitionPtr findDefinition(const toml::table& table, ParseContext& context) {
  const auto name = context.string(table, "lattice");
  if (!name) context.fail(table, "a lattice object needs `lattice = \"NAME\"` naming a [[lattices]] entry");
  const DefinitionMap& known = definitions(context);
  const auto it = known.find(*name);
  if (it == known.end()) {
    std::string names;
    for (const auto& [n, d] : known) names += (names.empty() ? "" : ", ") + n;
    context.fail(*table.get("lattice"), fmt::format("no lattice named '{}' is defined in [[lattices]] (defined: {})",
                                                    *name, names.empty() ? "none" : names));
  }
  return it->second;
}

void parseLatticeSection(const toml::node& section, ParseContext& context) {
  const toml::array* list = section.as_array();
  if (!list) context.fail(section, "[[lattices]] must be an array of tables (write `[[lattices]]`)");
  for (const toml::node& entry : *list) {
    const toml::table* table = entry.as_table();
    if (!table) context.fail(entry, "each [[lattices]] entry must be a table");
    context.checkKeys(*table, {"name", "spacing", "oversample", "cache", "object", "shadows", "precision"});
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
    if (const auto cache = context.string(*table, "cache")) {
      std::filesystem::path path(*cache);
      def->cache = path.is_absolute() ? path : context.file().parent_path() / path;
    }
    const toml::node* object = table->get("object");
    if (!object || !object->is_table())
      context.fail(*table, "a [[lattices]] entry needs `object = { type = ..., ... }`, the solid to rasterize");
    def->object = context.parseNode(*object);
    def->objectText = canonicalToml(*object);
    DefinitionMap& known = definitions(context);
    if (known.count(def->name)) context.fail(*table->get("name"), fmt::format("lattice '{}' is defined twice", def->name));
    known[def->name] = def;
    if (capturedDefinitions) capturedDefinitions->push_back(def);
  }
}

NodeDesc parsePolylineNode(const toml::table& table, ParseContext& context) {
  context.checkKeys(table, {"points", "radius"}, true);
  const double radius = context.positiveNumber(table, "radius");
  const toml::array* list = table.get("points") ? table.get("points")->as_array() : nullptr;
  if (!list || list->size() < 2)
    context.fail(table, "a polyline needs `points = [[x, y, z], [x, y, z], ...]` with at least two points");
  std::vector<Vec3d> points;
  for (const toml::node& p : *list) points.push_back(context.toVec3(p, "a polyline point"));
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i] == points[i - 1]) context.fail((*list)[i], "this polyline point repeats the one before it");
  return NodeDesc::makeLeaf(makePolylineLeafDesc(std::move(points), radius), context.where(table));
}

NodeDesc parseLatticeNode(const toml::table& table, ParseContext& context) {
  context.checkKeys(table, {"lattice"}, true);
  return NodeDesc::makeLeaf(makeLatticeLeafDesc(findDefinition(table, context)), context.where(table));
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

NodeDesc parseScatterNode(const toml::table& table, ParseContext& context) {
  context.checkKeys(table, {"lattice", "count", "radius", "seed"}, true);
  const LatticeDefinitionPtr def = findDefinition(table, context);
  const long long count = context.integer(table, "count").value_or(0);
  if (count < 1 || count > kMaxScatterCount)
    context.fail(table, fmt::format("`count` must be an integer between 1 and {} (how many instances to scatter; "
                                    "the limit is kMaxScatterCount, docs/limits.md)",
                                    kMaxScatterCount));
  const double radius = context.positiveNumber(table, "radius");
  const auto seed = static_cast<std::uint64_t>(context.integer(table, "seed").value_or(1));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> twist(0.0, 2.0 * std::numbers::pi);
  const LeafDescPtr leaf = makeLatticeLeafDesc(def);
  std::vector<NodeDesc> instances;
  instances.reserve(static_cast<std::size_t>(count));
  const std::string where = context.where(table);
  for (const Vec3d& p : fibonacciSphere(static_cast<int>(count))) {
    NodeDesc instance = NodeDesc::makeLeaf(leaf, where);
    const Mat4d spin = glm::rotate(Mat4d(1.0), twist(random), Vec3d(0, 0, 1));
    instance.transform = glm::translate(Mat4d(1.0), p * radius) * alignZ(p) * spin;
    instances.push_back(std::move(instance));
  }
  return NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(instances), where);
}

}  // namespace

std::uint64_t LatticeDefinition::hashFor(LhtPrecision form) const {
  // From our canonical form of the values (lht/canonical_toml.hpp), never a
  // formatter's output (toml++ 3.3.0's formatter overflowed a float-to-int
  // cast on small numbers in nested arrays: issue 15). "lattice2" marks the
  // key's second form: caches keyed by the formatter's text are refused as
  // rasterized from another definition (docs/lattices.md). The thesis's
  // precision adds nothing to the key.
  const std::string formText =
      form == LhtPrecision::Thesis ? "" : fmt::format(" precision={}", lhtPrecisionName(form));
  return fnv1a64(fmt::format("lattice2 spacing={} oversample={}{} object={}", canonicalDouble(lambda),
                             canonicalDouble(oversample), formText, objectText));
}

LhtFile LatticeDefinition::rasterizeNow(bool progress, RasterStats* stats, unsigned threads) const {
  try {
    const LatticeObject solid = sceneObject(object, objectText);
    LhtFile lht;
    lht.box = LatticeBox(solid.bounds, lambda, oversample);
    RasterOptions options;
    options.progress = progress;
    options.threads = threads;
    const RasterResult raster = rasterize(lht.box, *solid.primitive, options);
    const LhtPrecision form =
        packing ? packing(raster.hits.size(), raster.hits.capacity() * sizeof(RasterHit)) : precision;
    lht.objectHash = hashFor(form);
    lht.pairs = raster.stats.pairs;
    lht.hits = raster.stats.hits;
    lht.table = LatticeHashTable(raster.hits, form);
    if (stats) *stats = raster.stats;
    return lht;
  } catch (const Error& e) {
    throw Error(e.kind(), fmt::format("{}: lattice '{}': {}", origin, name, e.what()));
  }
}

const Bounds<double>& LatticeDefinition::objectBounds() const {
  // Every instance asks; building the exact object once is enough.
  std::call_once(boundsOnce_, [&] { bounds_ = sceneObject(object, objectText).bounds; });
  return bounds_;
}

std::shared_ptr<const LhtFile> LatticeDefinition::table(bool progress) const {
  std::call_once(once_, [&] {
    if (cache && std::filesystem::exists(*cache)) {
      table_ = std::make_shared<const LhtFile>(readLhtFile(*cache, hash(), precision));
      return;
    }
    auto lht = std::make_shared<const LhtFile>(rasterizeNow(progress, nullptr, rasterThreads));
    if (cache && lht->table.precision() == precision) writeLhtFile(*cache, *lht);
    table_ = std::move(lht);
  });
  return table_;
}

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

LeafDescPtr makeLatticeLeafDesc(LatticeDefinitionPtr definition) {
  return std::make_shared<LatticeLeafDesc>(std::move(definition));
}

void registerLatticeSceneTypes() {
  static std::once_flag once;
  std::call_once(once, [] {
    registerSection("lattices", parseLatticeSection);
    registerNodeType("lattice", parseLatticeNode);
    registerNodeType("lattice_scatter", parseScatterNode);
    registerNodeType("polyline", parsePolylineNode);
  });
}

namespace {

template <typename Load>
SceneWithLattices captureDefinitions(Load load) {
  registerLatticeSceneTypes();
  SceneWithLattices found;
  capturedDefinitions = &found.lattices;
  try {
    found.scene = load();
  } catch (...) {
    capturedDefinitions = nullptr;
    throw;
  }
  capturedDefinitions = nullptr;
  return found;
}

}  // namespace

SceneWithLattices loadSceneWithLattices(const std::filesystem::path& sceneFile) {
  return captureDefinitions([&] { return loadScene(sceneFile); });
}

SceneWithLattices parseSceneWithLattices(std::string_view text, const std::filesystem::path& fileName) {
  return captureDefinitions([&] { return parseScene(text, fileName); });
}

std::vector<LatticeDefinitionPtr> loadLatticeDefinitions(const std::filesystem::path& sceneFile) {
  return loadSceneWithLattices(sceneFile).lattices;
}

std::vector<LatticeDefinitionPtr> parseLatticeDefinitions(std::string_view text, const std::filesystem::path& fileName) {
  return parseSceneWithLattices(text, fileName).lattices;
}

}  // namespace lattice::lht
