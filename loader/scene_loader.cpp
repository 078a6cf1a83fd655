#include "loader/scene_loader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <vector>

#include "loader/node_types.hpp"
#include "loader/scene_text.hpp"
#include "foundation/transform_condition.hpp"
#include "foundation/error.hpp"

namespace lattice {

namespace {

// Keys every object table may have, handled by parseNode itself.
constexpr std::string_view kCommonNodeKeys[] = {"type", "name", "material", "translate", "rotate", "scale", "matrix"};
constexpr std::string_view kBuiltinSections[] = {"camera", "lights", "materials", "options", "objects"};
constexpr int kMaxNesting = 64;

std::string typeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

std::string joinKeys(std::span<const std::string_view> keys, bool withCommon) {
  std::vector<std::string> all(keys.begin(), keys.end());
  if (withCommon)
    for (auto k : kCommonNodeKeys) all.emplace_back(k);
  return all.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(all, ", "));
}

// Degenerate transforms collapse the solid (a zero scale) or make the
// inverse (world -> object, used by every ray) lose the digits rays need
// (render/transform_condition.hpp). A uniformly tiny or huge but well-shaped
// transform is fine within 1e-9..1e9 per axis.
std::string transformProblem(const Mat4d& m) {
  const std::string conditioning = conditionProblem(m, kMaxTransformCondition);
  if (!conditioning.empty()) return conditioning;
  for (int c = 0; c < 3; ++c) {
    const double length = glm::length(Vec3d(m[c]));
    if (!(length >= 1e-9 && length <= 1e9))
      return fmt::format("the transform scales the {} axis by {:.3g}, outside 1e-9..1e9; change the shape's own "
                         "size instead (e.g. its radius) so that scale factors stay in that range",
                         "xyz"[c], length);
  }
  return {};
}

// Transforms are checked one node at a time as they are read; their products
// down the tree (a squashed union holding a squashed child) are checked here,
// at every leaf, naming the leaf.
void checkComposedTransforms(const NodeDesc& node, const Mat4d& parentToWorld, const std::string& parentOrigin = {}) {
  const Mat4d toWorld = parentToWorld * node.transform;
  const std::string& origin = node.origin.empty() ? parentOrigin : node.origin;
  if (node.kind == NodeDesc::Kind::Leaf) {
    const std::string problem = transformProblem(toWorld);
    if (!problem.empty())
      throw Error(ErrorKind::Input, fmt::format("{}: with the transforms of the objects around it, {}", origin,
                                                problem));
    return;
  }
  for (const NodeDesc& child : node.children) checkComposedTransforms(child, toWorld, origin);
}

Mat4d rotation(const Vec3d& axis, double degrees) {
  const Vec3d a = glm::normalize(axis);
  const double r = degrees * 3.14159265358979323846 / 180.0;
  const double c = std::cos(r), s = std::sin(r), t = 1.0 - c;
  // Rodrigues' formula; glm is column-major: m[column][row].
  Mat4d m(1.0);
  m[0][0] = c + a.x * a.x * t;
  m[0][1] = a.y * a.x * t + a.z * s;
  m[0][2] = a.z * a.x * t - a.y * s;
  m[1][0] = a.x * a.y * t - a.z * s;
  m[1][1] = c + a.y * a.y * t;
  m[1][2] = a.z * a.y * t + a.x * s;
  m[2][0] = a.x * a.z * t + a.y * s;
  m[2][1] = a.y * a.z * t - a.x * s;
  m[2][2] = c + a.z * a.z * t;
  return m;
}

}  // namespace

void SceneFormat::addNodeType(std::string type, NodeParser parser) {
  nodeTypes[std::move(type)] = std::move(parser);
}

void SceneFormat::addSection(std::string name, SectionParser parser) {
  for (auto& [existing, p] : sections)
    if (existing == name) {
      p = std::move(parser);
      return;
    }
  sections.emplace_back(std::move(name), std::move(parser));
}

SceneFormat builtinSceneFormat() { return SceneFormat{builtinNodeTypes(), {}}; }

// ---------------------------------------------------------------- ParseContext

ParseContext::ParseContext(std::filesystem::path file, SceneDesc& scene, const SceneFormat& format)
    : file_(std::move(file)), scene_(scene), format_(format) {}

std::string ParseContext::where(const toml::node& node) const {
  const auto& begin = node.source().begin;
  if (begin.line == 0) return file_.string();
  return fmt::format("{}:{}:{}", file_.string(), begin.line, begin.column);
}

void ParseContext::fail(const toml::source_region& region, const std::string& message) const {
  throw Error(ErrorKind::Input, locate(file_.string(), static_cast<long>(region.begin.line),
                                       static_cast<long>(region.begin.column), message));
}

void ParseContext::fail(const toml::node& node, const std::string& message) const { fail(node.source(), message); }

void ParseContext::checkKeys(const toml::table& table, std::span<const std::string_view> allowed,
                             bool objectTable) const {
  for (auto&& [key, value] : table) {
    const std::string_view k = key.str();
    bool known = false;
    for (auto a : allowed) known = known || a == k;
    if (objectTable)
      for (auto a : kCommonNodeKeys) known = known || a == k;
    if (!known) {
      toml::source_region region = key.source();
      if (region.begin.line == 0) region = value.source();
      fail(region, fmt::format("unknown key '{}'; expected one of: {}", k, joinKeys(allowed, objectTable)));
    }
  }
}

double ParseContext::toNumber(const toml::node& node, std::string_view what) const {
  double v = 0;
  if (auto i = node.as_integer())
    v = static_cast<double>(i->get());
  else if (auto f = node.as_floating_point())
    v = f->get();
  else
    fail(node, fmt::format("'{}' must be a number, not {}", what, typeName(node)));
  if (!std::isfinite(v)) fail(node, fmt::format("'{}' must be a finite number (nan and inf are not allowed)", what));
  return v;
}

Vec3d ParseContext::toVec3(const toml::node& node, std::string_view what) const {
  const toml::array* a = node.as_array();
  if (!a || a->size() != 3)
    fail(node, fmt::format("'{}' must be an array of 3 numbers [x, y, z], not {}", what,
                           a ? fmt::format("an array of {}", a->size()) : typeName(node)));
  return {toNumber((*a)[0], what), toNumber((*a)[1], what), toNumber((*a)[2], what)};
}

std::optional<double> ParseContext::number(const toml::table& table, std::string_view key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  return toNumber(*n, key);
}

double ParseContext::requiredNumber(const toml::table& table, std::string_view key) const {
  auto v = number(table, key);
  if (!v) fail(table, fmt::format("missing key '{}' (a number)", key));
  return *v;
}

double ParseContext::positiveNumber(const toml::table& table, std::string_view key) const {
  double v = requiredNumber(table, key);
  if (!(v > 0)) fail(*table.get(key), fmt::format("'{}' must be > 0, got {}", key, v));
  return v;
}

std::optional<long long> ParseContext::integer(const toml::table& table, std::string_view key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  auto i = n->as_integer();
  if (!i) fail(*n, fmt::format("'{}' must be an integer, not {}", key, typeName(*n)));
  return i->get();
}

std::optional<bool> ParseContext::boolean(const toml::table& table, std::string_view key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  auto b = n->as_boolean();
  if (!b) fail(*n, fmt::format("'{}' must be true or false, not {}", key, typeName(*n)));
  return b->get();
}

std::optional<std::string> ParseContext::string(const toml::table& table, std::string_view key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  auto s = n->as_string();
  if (!s) fail(*n, fmt::format("'{}' must be a string, not {}", key, typeName(*n)));
  return s->get();
}

std::optional<Vec3d> ParseContext::vec3(const toml::table& table, std::string_view key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  return toVec3(*n, key);
}

Vec3d ParseContext::requiredVec3(const toml::table& table, std::string_view key) const {
  auto v = vec3(table, key);
  if (!v) fail(table, fmt::format("missing key '{}' (an array [x, y, z])", key));
  return *v;
}

std::optional<Vec3d> ParseContext::color(const toml::table& table, std::string_view key) const {
  const toml::node* n = table.get(key);
  if (!n) return std::nullopt;
  Vec3d c = n->is_array() ? toVec3(*n, key) : Vec3d(toNumber(*n, key));
  if (c.x < 0 || c.y < 0 || c.z < 0)
    fail(*n, fmt::format("'{}' must be >= 0 in every channel (one number or [r, g, b])", key));
  return c;
}

MaterialId ParseContext::material(const toml::node& nameNode) const {
  auto s = nameNode.as_string();
  if (!s) fail(nameNode, fmt::format("'material' must be a material name (a string), not {}", typeName(nameNode)));
  if (auto id = scene_.findMaterial(s->get())) return *id;
  std::vector<std::string> names;
  for (const auto& m : scene_.materials) names.push_back(m.name);
  fail(nameNode, fmt::format("unknown material '{}'; define it as [materials.{}] or use one of: {}", s->get(),
                             s->get(), fmt::join(names, ", ")));
}

Mat4d ParseContext::transform(const toml::table& table) const {
  Mat4d m(1.0);
  const toml::node* where = nullptr;
  if (const toml::node* mat = table.get("matrix")) {
    where = mat;
    for (auto k : {"translate", "rotate", "scale"})
      if (table.get(k)) fail(*table.get(k), fmt::format("'{}' cannot be combined with 'matrix'; fold it into the matrix", k));
    const toml::array* rows = mat->as_array();
    if (!rows || rows->size() != 4)
      fail(*mat, "'matrix' must be 4 rows of 4 numbers: [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz], [0, 0, 0, 1]]");
    for (std::size_t r = 0; r < 4; ++r) {
      const toml::array* row = (*rows)[r].as_array();
      if (!row || row->size() != 4) fail((*rows)[r], fmt::format("'matrix' row {} must be an array of 4 numbers", r + 1));
      for (std::size_t c = 0; c < 4; ++c) m[static_cast<int>(c)][static_cast<int>(r)] = toNumber((*row)[c], "matrix");
    }
    if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
      fail(*mat, "'matrix' must be affine: its last row must be [0, 0, 0, 1]");
  } else {
    Mat4d s(1.0), r(1.0), t(1.0);
    if (const toml::node* sc = table.get("scale")) {
      where = sc;
      Vec3d f = sc->is_array() ? toVec3(*sc, "scale") : Vec3d(toNumber(*sc, "scale"));
      s[0][0] = f.x;
      s[1][1] = f.y;
      s[2][2] = f.z;
    }
    if (const toml::node* ro = table.get("rotate")) {
      where = ro;
      auto one = [&](const toml::node& n) {
        const toml::table* rt = n.as_table();
        if (!rt) fail(n, "'rotate' must be a table { axis = [x, y, z], degrees = a } or an array of them");
        checkKeys(*rt, {"axis", "degrees"});
        Vec3d axis = requiredVec3(*rt, "axis");
        if (glm::length(axis) < 1e-12) fail(*rt->get("axis"), "'axis' of 'rotate' must be a non-zero vector");
        return rotation(axis, requiredNumber(*rt, "degrees"));
      };
      if (const toml::array* list = ro->as_array()) {
        // Applied in the order written: the first rotation acts first.
        for (const toml::node& n : *list) r = one(n) * r;
      } else {
        r = one(*ro);
      }
    }
    if (const toml::node* tr = table.get("translate")) {
      where = where ? where : tr;
      Vec3d d = toVec3(*tr, "translate");
      t[3] = glm::dvec4(d, 1.0);
    }
    m = t * r * s;
  }
  if (where) {
    const std::string problem = transformProblem(m);
    if (!problem.empty()) fail(*where, problem);
  }
  return m;
}

NodeDesc ParseContext::parseNode(const toml::node& objectNode) {
  const toml::table* table = objectNode.as_table();
  if (!table)
    fail(objectNode, fmt::format("an object must be a table with a 'type' key, not {}", typeName(objectNode)));
  if (depth_ >= kMaxNesting) fail(objectNode, fmt::format("objects are nested more than {} deep", kMaxNesting));
  const toml::node* typeNode = table->get("type");
  if (!typeNode) fail(*table, "object has no 'type' key; expected e.g. type = \"sphere\" or type = \"union\"");
  auto typeString = typeNode->as_string();
  if (!typeString) fail(*typeNode, fmt::format("'type' must be a string, not {}", typeName(*typeNode)));
  const std::string type = typeString->get();

  const auto found = format_.nodeTypes.find(type);
  if (found == format_.nodeTypes.end()) {
    std::vector<std::string> known;
    for (auto& [name, p] : format_.nodeTypes) known.push_back(name);
    fail(*typeNode, fmt::format("unknown object type '{}'; expected one of: {}", type, fmt::join(known, ", ")));
  }
  const NodeParser& parser = found->second;
  (void)string(*table, "name");  // only type-checked: names are for the reader
  const Mat4d local = transform(*table);
  std::optional<MaterialId> materialId;
  if (const toml::node* mn = table->get("material")) materialId = material(*mn);

  ++depth_;
  NodeDesc node;
  try {
    node = parser(*table, *this);
  } catch (...) {
    --depth_;
    throw;
  }
  --depth_;
  node.transform = local * node.transform;
  if (materialId && !node.material) node.material = materialId;
  if (node.origin.empty()) node.origin = where(*table);
  return node;
}

std::vector<NodeDesc> ParseContext::parseChildren(const toml::table& table, std::string_view key) {
  const toml::node* n = table.get(key);
  if (!n) fail(table, fmt::format("missing key '{}' (an array of object tables)", key));
  const toml::array* list = n->as_array();
  if (!list) fail(*n, fmt::format("'{}' must be an array of object tables, not {}", key, typeName(*n)));
  std::vector<NodeDesc> out;
  out.reserve(list->size());
  for (const toml::node& child : *list) out.push_back(parseNode(child));
  return out;
}

// ---------------------------------------------------------------- sections

namespace {

void parseOptions(const toml::table& t, ParseContext& ctx) {
  ctx.checkKeys(t, {"ambient", "K", "background", "width", "height", "shadows"});
  SceneOptions& o = ctx.scene().options;
  if (auto v = ctx.color(t, "ambient")) o.ambient = *v;
  if (auto v = ctx.number(t, "K")) o.attenuationK = *v;
  if (auto v = ctx.color(t, "background")) {
    if (v->x > 1 || v->y > 1 || v->z > 1) ctx.fail(*t.get("background"), "'background' channels must be in [0, 1]");
    o.background = *v;
  }
  for (auto key : {"width", "height"}) {
    if (auto v = ctx.integer(t, key)) {
      if (*v < 1 || *v > 16384) ctx.fail(*t.get(key), fmt::format("'{}' must be between 1 and 16384 pixels", key));
      (std::string_view(key) == "width" ? o.width : o.height) = static_cast<int>(*v);
    }
  }
  if (auto v = ctx.boolean(t, "shadows")) o.shadows = *v;
}

void parseCamera(const toml::table& t, ParseContext& ctx) {
  CameraDesc& c = ctx.scene().camera;
  const std::string type = ctx.string(t, "type").value_or("thesis");
  if (type == "thesis") {
    ctx.checkKeys(t, {"type", "distance", "width", "height"});
    c.kind = CameraDesc::Kind::Thesis;
    c.distance = ctx.positiveNumber(t, "distance");
    c.displayWidth = ctx.positiveNumber(t, "width");
    c.displayHeight = ctx.positiveNumber(t, "height");
  } else if (type == "look_at") {
    ctx.checkKeys(t, {"type", "eye", "target", "up", "fov"});
    c.kind = CameraDesc::Kind::LookAt;
    c.eye = ctx.requiredVec3(t, "eye");
    c.target = ctx.requiredVec3(t, "target");
    c.up = ctx.vec3(t, "up").value_or(Vec3d(0, 1, 0));
    c.fovDegrees = ctx.number(t, "fov").value_or(45.0);
  } else {
    ctx.fail(*t.get("type"), fmt::format("unknown camera type '{}'; expected \"thesis\" or \"look_at\"", type));
  }
  validateCamera(c, ctx.where(t) + ": [camera]");
}

void parseLights(const toml::node& n, ParseContext& ctx) {
  const toml::array* list = n.as_array();
  if (!list) ctx.fail(n, "'lights' must be an array of tables: write each light as [[lights]]");
  for (const toml::node& e : *list) {
    const toml::table* t = e.as_table();
    if (!t) ctx.fail(e, "each light must be a table with 'position' and 'intensity'");
    ctx.checkKeys(*t, {"position", "intensity"});
    PointLight<double> light;
    light.position = ctx.requiredVec3(*t, "position");
    auto intensity = ctx.color(*t, "intensity");
    if (!intensity) ctx.fail(*t, "missing key 'intensity' (one number or [r, g, b], the thesis's I_inc)");
    light.intensity = *intensity;
    ctx.scene().lights.push_back(light);
  }
}

void parseMaterials(const toml::table& t, ParseContext& ctx) {
  for (auto&& [key, value] : t) {
    const toml::table* m = value.as_table();
    if (!m) ctx.fail(value, fmt::format("material '{}' must be a table: [materials.{}]", key.str(), key.str()));
    ctx.checkKeys(*m, {"ambient", "diffuse", "specular", "shininess"});
    Material<double> mat;
    if (auto v = ctx.color(*m, "ambient")) mat.ambient = *v;
    if (auto v = ctx.color(*m, "diffuse")) mat.diffuse = *v;
    if (auto v = ctx.color(*m, "specular")) mat.specular = *v;
    if (auto v = ctx.color(*m, "shininess")) mat.shininess = *v;
    ctx.scene().addMaterial(std::string(key.str()), mat);
  }
}

const toml::table& requireTable(const toml::node& n, std::string_view name, ParseContext& ctx) {
  const toml::table* t = n.as_table();
  if (!t) ctx.fail(n, fmt::format("'{}' must be a table: write it as [{}]", name, name));
  return *t;
}

SceneDesc parseTable(const toml::table& root, const std::filesystem::path& file, const SceneFormat& format) {
  SceneDesc scene;
  scene.source = file;
  ParseContext ctx(file, scene, format);
  const auto& sections = format.sections;
  for (auto&& [key, value] : root) {
    const std::string_view k = key.str();
    bool known = false;
    for (auto b : kBuiltinSections) known = known || b == k;
    for (auto& [name, p] : sections) known = known || name == k;
    if (!known) {
      std::vector<std::string> names(std::begin(kBuiltinSections), std::end(kBuiltinSections));
      for (auto& [name, p] : sections) names.push_back(name);
      ctx.fail(key.source().begin.line ? key.source() : value.source(),
               fmt::format("unknown section '{}'; expected one of: {}", k, fmt::join(names, ", ")));
    }
  }

  if (const toml::node* n = root.get("options")) parseOptions(requireTable(*n, "options", ctx), ctx);
  if (const toml::node* n = root.get("materials")) parseMaterials(requireTable(*n, "materials", ctx), ctx);
  if (const toml::node* n = root.get("camera")) parseCamera(requireTable(*n, "camera", ctx), ctx);
  if (const toml::node* n = root.get("lights")) parseLights(*n, ctx);
  for (auto& [name, parser] : sections)
    if (const toml::node* n = root.get(name)) parser(*n, ctx);

  const toml::node* objects = root.get("objects");
  if (!objects)
    throw Error(ErrorKind::Input, locate(file.string(), 0, 0,
                                         "the scene has no objects; add at least one [[objects]] table with a 'type'"));
  const toml::array* list = objects->as_array();
  if (!list || list->empty()) ctx.fail(*objects, "'objects' must be a non-empty array of tables: write each as [[objects]]");
  std::vector<NodeDesc> top;
  for (const toml::node& o : *list) top.push_back(ctx.parseNode(o));
  scene.root = top.size() == 1 ? std::move(top.front())
                               : NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(top), file.string());
  checkComposedTransforms(scene.root, Mat4d(1.0));
  return scene;
}

}  // namespace

SceneDesc parseScene(std::string_view text, const std::filesystem::path& fileName, const SceneFormat& format) {
  checkSceneText(text, fileName.string());  // before toml++ sees it: loader/scene_text.hpp
  toml::table root;
  try {
    root = toml::parse(text, fileName.string());
  } catch (const toml::parse_error& e) {
    throw Error(ErrorKind::Input, locate(fileName.string(), static_cast<long>(e.source().begin.line),
                                         static_cast<long>(e.source().begin.column),
                                         fmt::format("not valid TOML: {}", e.description())));
  }
  return parseTable(root, fileName, format);
}

SceneDesc loadScene(const std::filesystem::path& file, const SceneFormat& format) {
  // Read whole (at most kMaxSceneBytes), so the text can be checked first.
  return parseScene(readSceneText(file.string()), file, format);
}

}  // namespace lattice
