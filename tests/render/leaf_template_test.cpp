// Leaves are written once, as a template (render/scene/scene.hpp LeafTemplate):
// building a tree for any arithmetic reaches the leaf's buildAs<T> with the
// leaf's placement, material and build options.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "foundation/error.hpp"
#include "render/shapes/quartic.hpp"
#include "render/scene/scene.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;

namespace {

class RecordingLeaf final : public LeafTemplate<RecordingLeaf> {
 public:
  explicit RecordingLeaf(std::vector<std::string>& log) : log_(&log) {}
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId material, const BuildOptions& options) const {
    log_->push_back(std::string(arithmeticName<T>()) + (options.fullRayTrace ? " full" : "") +
                    " material " + std::to_string(material) + " x " + std::to_string(toWorld[3].x));
    const QuarticShape ball = sphere(1.0);
    return makeQuarticLeaf<T>(ball.f, ball.bounds, toWorld, material);
  }
  Bounds<double> objectBounds() const override { return {Vec3d(-1.0), Vec3d(1.0)}; }
  std::string describe() const override { return "recording leaf"; }

 private:
  std::vector<std::string>* log_;
};

}  // namespace

TEST_CASE("leaves: one template build serves every arithmetic") {
  std::vector<std::string> log;
  NodeDesc leaf = NodeDesc::makeLeaf(std::make_shared<RecordingLeaf>(log), "test");
  leaf.transform[3] = glm::dvec4(2, 0, 0, 1);
  leaf.material = 3;
  BuildOptions options;
  REQUIRE(buildPrimitive<float>(leaf, Mat4d(1.0), options));
  REQUIRE(buildPrimitive<Fixed32>(leaf, Mat4d(1.0), options));
  options.fullRayTrace = true;
  const PrimitivePtr<double> built = buildPrimitive<double>(leaf, Mat4d(1.0), options);
  REQUIRE(built);
  CHECK(log == std::vector<std::string>{"float material 3 x 2.000000", "fixed material 3 x 2.000000",
                                        "double full material 3 x 2.000000"});
  // What it built is what the leaf made: the unit sphere moved to x = 2.
  Hit<double> hit;
  REQUIRE(built->firstHit(Ray<double>{Vec3d(2, 0, -5), Vec3d(0, 0, 1)}, 0.0, 100.0, hit));
  CHECK(hit.t == Approx(4.0));
  CHECK(hit.material == 3);
}

namespace {

class FailingLeaf final : public LeafTemplate<FailingLeaf> {
 public:
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d&, MaterialId, const BuildOptions&) const {
    throw Error(ErrorKind::Input, "cannot be built");
  }
  Bounds<double> objectBounds() const override { return {Vec3d(-1.0), Vec3d(1.0)}; }
  std::string describe() const override { return "failing leaf"; }
};

}  // namespace

TEST_CASE("leaves: a leaf without a place of its own is named by its parent's") {
  // A scatter's instances hold no origin: the union's is theirs (NodeDesc::origin).
  std::vector<NodeDesc> instances;
  instances.push_back(NodeDesc::makeLeaf(std::make_shared<FailingLeaf>()));
  instances.push_back(NodeDesc::makeLeaf(std::make_shared<FailingLeaf>()));
  const NodeDesc scatter = NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(instances), "hairs.toml:12:1");
  CHECK_THROWS_WITH(buildPrimitive<double>(scatter, Mat4d(1.0), BuildOptions{}), "hairs.toml:12:1: cannot be built");
  // With no place anywhere, the scene is named.
  CHECK_THROWS_WITH(buildPrimitive<double>(scatter.children[0], Mat4d(1.0), BuildOptions{}),
                    "scene: cannot be built");
}
