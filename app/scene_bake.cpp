#include "app/scene_bake.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "render/scene/scene_baker.hpp"

namespace lattice::app {
namespace {

constexpr const char* kKinds[] = {"Leaf", "Union", "Intersection", "Difference"};

class CppSceneBaker final : public SceneBaker {
 public:
  std::string number(double v) const override {
    if (std::isnan(v)) return "std::numeric_limits<double>::quiet_NaN()";
    if (std::isinf(v)) return v > 0 ? "std::numeric_limits<double>::infinity()" : "-std::numeric_limits<double>::infinity()";
    return fmt::format("{:a}", v);
  }

  // Every node is a function of its own, returning the NodeDesc: one
  // function holding a thousand temporaries (a braced list of children, a
  // lambda per instance) would need a stack frame of hundreds of KiB on the
  // MCU; separate functions and push_back keep each frame small.
  //
  // A union whose children are all leaves of one description (a scatter's
  // instances) is offered to that description first (LeafDesc::bakeUnion):
  // a lattice writes its instances and their BVH as constant data, one leaf
  // node for the lot. The walk carries each node's world map and inherited
  // material for that; a subtree a leaf bakes itself (node()) starts at the
  // identity, and the baked union checks the map it is built with.
  std::string node(const NodeDesc& n) override { return walk(n, Mat4d(1.0), 0); }

  std::string walk(const NodeDesc& n, const Mat4d& parentToWorld, MaterialId inherited) {
    const std::string name = fmt::format("node{}", functions_.size());
    functions_.emplace_back();  // reserve the number; the body is written below
    std::string body;
    const std::string instances = instanceUnion(n, parentToWorld, inherited);
    if (!instances.empty()) {
      ++leaves_;
      instances_ += n.children.size();
      body = fmt::format("  lattice::NodeDesc n = lattice::NodeDesc::makeLeaf({});\n", instances);
    } else if (n.kind == NodeDesc::Kind::Leaf) {
      ++leaves_;
      body = fmt::format("  lattice::NodeDesc n = lattice::NodeDesc::makeLeaf({});\n", n.leaf->bake(*this));
    } else {
      const Mat4d toWorld = parentToWorld * n.transform;
      const MaterialId material = n.material.value_or(inherited);
      body = fmt::format("  std::vector<lattice::NodeDesc> children;\n  children.reserve({});\n", n.children.size());
      for (const NodeDesc& c : n.children)
        body += fmt::format("  children.push_back({}());\n", walk(c, toWorld, material));
      body += fmt::format("  lattice::NodeDesc n = lattice::NodeDesc::makeOperation(lattice::NodeDesc::Kind::{}, "
                          "std::move(children));\n",
                          kKinds[static_cast<int>(n.kind)]);
    }
    if (n.transform != Mat4d(1.0)) body += fmt::format("  n.transform = {};\n", mat4(n.transform));
    if (n.material) body += fmt::format("  n.material = lattice::MaterialId{{{}}};\n", *n.material);
    functions_[std::stoul(name.substr(4))] =
        fmt::format("[[gnu::noinline]] lattice::NodeDesc {}() {{\n{}  return n;\n}}\n", name, body);
    return name;
  }

  std::string flashBytes(std::span<const std::uint8_t> bytes, std::string_view what) override {
    const std::string name = fmt::format("kFlash{}", arrays_.size());
    std::string text = fmt::format("// {}: {} bytes\nalignas(4) const std::uint8_t {}[] = {{", what, bytes.size(), name);
    for (std::size_t i = 0; i < bytes.size(); ++i) text += fmt::format("{}{}", i % 24 == 0 ? "\n  " : "", bytes[i]) + ",";
    text += "\n};\n";
    arrays_.push_back(std::move(text));
    flashBytes_ += bytes.size();
    return fmt::format("std::span<const std::uint8_t>({})", name);
  }

  std::string shared(const void* identity, const std::function<std::string()>& expression) override {
    const auto found = sharedNames_.find(identity);
    if (found != sharedNames_.end()) return found->second;
    // Built once, on first use, by a function-local static.
    const std::string name = fmt::format("shared{}", sharedNames_.size());
    sharedNames_.emplace(identity, name + "()");
    sharedDefinitions_ += fmt::format("const auto& {}() {{\n  static const auto value = {};\n  return value;\n}}\n",
                                      name, expression());
    return name + "()";
  }

  void include(std::string_view header) override { includes_.insert(std::string(header)); }
  void constantData(std::string definitions, std::size_t bytes) override {
    arrays_.push_back(std::move(definitions));
    flashBytes_ += bytes;
  }
  std::string freshName(std::string_view prefix) override { return fmt::format("{}{}", prefix, names_++); }
  bool defineOnce(std::string_view key) override { return defined_.insert(std::string(key)).second; }
  std::size_t instances() const { return instances_; }
  const std::string& sharedDefinitions() const { return sharedDefinitions_; }
  const std::vector<std::string>& functions() const { return functions_; }

  const std::set<std::string>& includes() const { return includes_; }
  const std::vector<std::string>& arrays() const { return arrays_; }
  std::size_t flashTotal() const { return flashBytes_; }
  std::size_t leaves() const { return leaves_; }

 private:
  std::set<std::string> includes_;
  std::map<const void*, std::string> sharedNames_;
  std::string sharedDefinitions_;
  std::vector<std::string> arrays_;
  std::size_t flashBytes_ = 0;
  std::size_t leaves_ = 0;
  std::vector<std::string> functions_;  // node{i}'s definition at [i]
  std::set<std::string> defined_;
  std::size_t names_ = 0;
  std::size_t instances_ = 0;  // leaves baked as constant data by a union

  // The expression of `n` baked by its children's shared description, or empty.
  std::string instanceUnion(const NodeDesc& n, const Mat4d& parentToWorld, MaterialId inherited) {
    if (n.kind != NodeDesc::Kind::Union || n.children.size() < 2) return {};
    const LeafDesc* shared = n.children[0].leaf.get();
    for (const NodeDesc& c : n.children)
      if (c.kind != NodeDesc::Kind::Leaf || !shared || c.leaf.get() != shared) return {};
    return shared->bakeUnion(*this, n, parentToWorld, inherited);
  }
};

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

BakeResult bakeScene(const lht::SceneWithLattices& loaded, const BakeRequest& request) {
  const SceneDesc& scene = loaded.scene;
  CppSceneBaker baker;
  const std::string root = baker.node(scene.root);

  std::string body;
  const CameraDesc& c = scene.camera;
  body += fmt::format("  s.camera.kind = lattice::CameraDesc::Kind::{};\n",
                      c.kind == CameraDesc::Kind::Thesis ? "Thesis" : "LookAt");
  body += fmt::format("  s.camera.distance = {};\n  s.camera.displayWidth = {};\n  s.camera.displayHeight = {};\n",
                      baker.number(c.distance), baker.number(c.displayWidth), baker.number(c.displayHeight));
  body += fmt::format("  s.camera.eye = {};\n  s.camera.target = {};\n  s.camera.up = {};\n  s.camera.fovDegrees = {};\n",
                      baker.vec3(c.eye), baker.vec3(c.target), baker.vec3(c.up), baker.number(c.fovDegrees));
  for (const auto& light : scene.lights)
    body += fmt::format("  s.lights.push_back({{{}, {}}});\n", baker.vec3(light.position), baker.vec3(light.intensity));
  body += "  s.materials.clear();\n";
  for (const auto& m : scene.materials)
    body += fmt::format("  s.materials.push_back({{{}, {{{}, {}, {}, {}}}}});\n", quoted(m.name),
                        baker.vec3(m.material.ambient), baker.vec3(m.material.diffuse),
                        baker.vec3(m.material.specular), baker.vec3(m.material.shininess));
  const SceneOptions& o = scene.options;
  body += fmt::format("  s.options.ambient = {};\n  s.options.attenuationK = {};\n  s.options.background = {};\n",
                      baker.vec3(o.ambient), baker.number(o.attenuationK), baker.vec3(o.background));
  body += fmt::format("  s.options.width = {};\n  s.options.height = {};\n  s.options.shadows = {};\n", o.width,
                      o.height, o.shadows ? "true" : "false");
  body += fmt::format("  s.root = {}();\n", root);

  const quantize::PipelineOptions& p = request.pipeline;
  std::string settings;
  for (const std::string& kv : request.settings) settings += (settings.empty() ? "" : ", ") + quoted(kv);

  std::string out = fmt::format(
      "// Generated by `lattice bake {} --size {}x{}`: the scene for the firmware (docs/firmware.md).\n"
      "// Do not edit; bake again. {} leaves, {} instances held as constant data, {} bytes of tables and instances in flash.\n"
      "#include <cstdint>\n#include <limits>\n#include <memory>\n#include <span>\n#include <vector>\n\n#include \"firmware/baked_scene.hpp\"\n",
      request.sceneFile, request.width, request.height, baker.leaves(), baker.instances(), baker.flashTotal());
  for (const std::string& h : baker.includes()) out += fmt::format("#include \"{}\"\n", h);
  out += "\nnamespace {\n\n";
  for (const std::string& a : baker.arrays()) out += a + "\n";
  out += baker.sharedDefinitions() + "\n";
  // Callees first, so each is declared before use: children get higher numbers.
  for (auto f = baker.functions().rbegin(); f != baker.functions().rend(); ++f) out += *f + "\n";
  out += "}  // namespace\n\n";
  out += "lattice::firmware::BakedScene lattice::firmware::bakedScene() {\n  BakedScene b;\n";
  out += fmt::format("  b.name = {};\n  b.width = {};\n  b.height = {};\n  b.settings = {{{}}};\n",
                     quoted(std::filesystem::path(request.sceneFile).stem().string()), request.width, request.height,
                     settings);
  out += fmt::format(
      "  b.pipeline.mode = static_cast<lattice::quantize::PipelineMode>({});\n  b.pipeline.sampleStep = {};\n"
      "  b.pipeline.maxColors = {};\n  b.pipeline.quantize.split = static_cast<lattice::quantize::SplitRule>({});\n"
      "  b.pipeline.quantize.refineIterations = {};\n"
      "  b.pipeline.quantize.dither = static_cast<lattice::quantize::Dither>({});\n"
      "  b.pipeline.quantize.histogram = static_cast<lattice::quantize::HistogramForm>({});\n"
      "  b.pipeline.progress = false;\n",
      static_cast<int>(p.mode), p.sampleStep, p.maxColors, static_cast<int>(p.quantize.split),
      p.quantize.refineIterations, static_cast<int>(p.quantize.dither), static_cast<int>(p.quantize.histogram));
  out += "  lattice::SceneDesc& s = b.scene;\n" + body + "  return b;\n}\n";
  return BakeResult{std::move(out), baker.flashTotal(), baker.leaves()};
}

}  // namespace lattice::app
