// The scene's tree built on the render's threads (render/scene/scene.cpp,
// foundation/ordered_parallel_for.hpp): a set operation of many operands is
// built on several threads, the tree answers every ray as the one-thread
// tree does, and a failure is the one the plain loop meets first.
#include <catch2/catch.hpp>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "foundation/error.hpp"
#include "render/scene/scene.hpp"
#include "render/shapes/quartic.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;

namespace {

// A unit sphere, placed and coloured by the node above it.
class BallLeaf final : public LeafTemplate<BallLeaf> {
 public:
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId material, const BuildOptions&) const {
    const QuarticShape ball = sphere(1.0);
    return makeQuarticLeaf<T>(ball.f, ball.bounds, toWorld, material);
  }
  Bounds<double> objectBounds() const override { return {Vec3d(-1.0), Vec3d(1.0)}; }
  std::string describe() const override { return "ball"; }
};

// `count` balls on a grid, their materials by their place in the union, so
// an operand built into another's slot shows as a wrong material.
NodeDesc balls(int count) {
  std::vector<NodeDesc> operands;
  for (int i = 0; i < count; ++i) {
    NodeDesc ball = NodeDesc::makeLeaf(std::make_shared<BallLeaf>(), "balls.toml:" + std::to_string(i));
    ball.transform[3] = glm::dvec4(3.0 * (i % 40), 3.0 * (i / 40), 0.0, 1.0);
    ball.material = static_cast<MaterialId>(i % 7);
    operands.push_back(std::move(ball));
  }
  return NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(operands), "balls.toml");
}

BuildOptions onThreads(unsigned threads) {
  BuildOptions options;
  options.threads = threads;
  return options;
}

// Records the threads that built it; until a second thread has built one of
// its kind, each build after the first waits (at most until `deadline`), so
// a build that is serial cannot pass by luck of timing.
struct ThreadLog {
  std::mutex mutex;
  std::condition_variable seen;
  std::set<std::thread::id> threads;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
};

class ThreadLeaf final : public LeafTemplate<ThreadLeaf> {
 public:
  explicit ThreadLeaf(ThreadLog& log) : log_(&log) {}
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d& toWorld, MaterialId material, const BuildOptions&) const {
    std::unique_lock lock(log_->mutex);
    const bool first = log_->threads.empty();
    log_->threads.insert(std::this_thread::get_id());
    log_->seen.notify_all();
    if (!first) log_->seen.wait_until(lock, log_->deadline, [&] { return log_->threads.size() > 1; });
    const QuarticShape ball = sphere(1.0);
    return makeQuarticLeaf<T>(ball.f, ball.bounds, toWorld, material);
  }
  Bounds<double> objectBounds() const override { return {Vec3d(-1.0), Vec3d(1.0)}; }
  std::string describe() const override { return "thread leaf"; }

 private:
  ThreadLog* log_;
};

// Fails, after `delay`, naming itself.
class LateFailingLeaf final : public LeafTemplate<LateFailingLeaf> {
 public:
  explicit LateFailingLeaf(std::chrono::milliseconds delay) : delay_(delay) {}
  template <typename T>
  PrimitivePtr<T> buildAs(const Mat4d&, MaterialId, const BuildOptions&) const {
    std::this_thread::sleep_for(delay_);
    throw Error(ErrorKind::Input, "cannot be built");
  }
  Bounds<double> objectBounds() const override { return {Vec3d(-1.0), Vec3d(1.0)}; }
  std::string describe() const override { return "failing leaf"; }

 private:
  std::chrono::milliseconds delay_;
};

}  // namespace

TEST_CASE("parallel build: a set operation of many operands is built on several threads") {
  ThreadLog log;
  std::vector<NodeDesc> leaves;
  for (int i = 0; i < 600; ++i) leaves.push_back(NodeDesc::makeLeaf(std::make_shared<ThreadLeaf>(log), "t"));
  const NodeDesc group = NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(leaves), "t");
  REQUIRE(buildPrimitive<double>(group, Mat4d(1.0), onThreads(4)));
  CHECK(log.threads.size() > 1);
}

TEST_CASE("parallel build: the tree answers every ray as the one-thread tree does, span for span") {
  const NodeDesc scene = balls(1200);
  const PrimitivePtr<double> one = buildPrimitive<double>(scene, Mat4d(1.0), onThreads(1));
  std::vector<int> materialsSeen(7, 0);
  for (unsigned threads : {2u, 3u, 8u}) {
    const PrimitivePtr<double> many = buildPrimitive<double>(scene, Mat4d(1.0), onThreads(threads));
    REQUIRE(many->bounds().lo == one->bounds().lo);
    REQUIRE(many->bounds().hi == one->bounds().hi);
    int hits = 0, differ = 0;
    for (int y = 0; y < 180; ++y)
      for (int x = 0; x < 240; ++x) {
        const Ray<double> ray{Vec3d(-2.0 + 0.5 * x, -2.0 + 0.5 * y, -10.0), Vec3d(0.01, 0.02, 1.0)};
        SpanList<double> a, b;
        one->spans(ray, 0.0, 100.0, a);
        many->spans(ray, 0.0, 100.0, b);
        if (!a.empty()) {
          ++hits;
          ++materialsSeen[a[0].enter.material];
        }
        bool same = a.size() == b.size();
        for (std::size_t k = 0; same && k < a.size(); ++k)
          same = a[k].enter.t == b[k].enter.t && a[k].leave.t == b[k].leave.t &&
                 a[k].enter.material == b[k].enter.material && a[k].leave.material == b[k].leave.material &&
                 a[k].enter.normal == b[k].enter.normal;
        if (!same) ++differ;
      }
    CHECK(hits > 10000);
    CHECK(differ == 0);
  }
  // The rays meet balls of every material.
  for (int seen : materialsSeen) CHECK(seen > 0);
}

TEST_CASE("parallel build: the error is the first operand's that fails, at every thread count") {
  std::vector<NodeDesc> leaves;
  for (int i = 0; i < 1000; ++i) {
    const std::string where = "hairs.toml:" + std::to_string(i) + ":1";
    if (i == 300)  // fails late, after operand 700 has failed on another thread
      leaves.push_back(NodeDesc::makeLeaf(std::make_shared<LateFailingLeaf>(std::chrono::milliseconds(200)), where));
    else if (i == 700)
      leaves.push_back(NodeDesc::makeLeaf(std::make_shared<LateFailingLeaf>(std::chrono::milliseconds(0)), where));
    else
      leaves.push_back(NodeDesc::makeLeaf(std::make_shared<BallLeaf>(), where));
  }
  const NodeDesc scatter = NodeDesc::makeOperation(NodeDesc::Kind::Union, std::move(leaves), "hairs.toml:1:1");
  for (unsigned threads : {1u, 2u, 4u})
    CHECK_THROWS_WITH(buildPrimitive<double>(scatter, Mat4d(1.0), onThreads(threads)),
                      "hairs.toml:300:1: cannot be built");
}
