// The BVH built on threads (render/accel/bvh.cpp: the two subtrees of the top
// splits at once) is the tree the one-thread build makes, node for node.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "foundation/fixed.hpp"
#include "render/accel/bvh.hpp"
#include "render/accel/wide_bvh.hpp"

using namespace lattice;

namespace {

// Boxes scattered in clusters (uneven splits), with a run of identical boxes
// no plane separates (the median split).
template <typename T>
std::vector<Bounds<T>> scatteredBoxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> cluster(-20, 20), spread(-1.5, 1.5), size(0.02, 0.3);
  std::vector<Bounds<T>> boxes;
  Vec3d centre(0.0);
  for (int i = 0; i < n; ++i) {
    if (i % 500 == 0) centre = Vec3d(cluster(rng), cluster(rng), cluster(rng));
    const Vec3d c = centre + Vec3d(spread(rng), spread(rng), spread(rng));
    const double r = size(rng);
    boxes.push_back({Vec3<T>(c - r), Vec3<T>(c + r)});
  }
  for (int i = 0; i < 300; ++i) boxes.push_back(boxes[7]);
  return boxes;
}

}  // namespace

TEMPLATE_TEST_CASE("BVH on threads: the same nodes and items as on one", "[bvh]", float, double, Fixed32) {
  using T = TestType;
  const std::vector<Bounds<T>> boxes = scatteredBoxes<T>(6000, 11);
  const Bvh<T> one(boxes, 1);
  REQUIRE(one.nodes().size() > 1000);
  for (unsigned threads : {2u, 3u, 4u, 8u}) {
    const Bvh<T> many(boxes, threads);
    CHECK(many.depth() == one.depth());
    REQUIRE(many.nodes().size() == one.nodes().size());
    REQUIRE(many.items().size() == one.items().size());
    int differ = 0;
    for (std::size_t n = 0; n < one.nodes().size(); ++n) {
      const auto &a = one.nodes()[n], &b = many.nodes()[n];
      if (a.first != b.first || a.count != b.count || a.box.lo != b.box.lo || a.box.hi != b.box.hi) ++differ;
    }
    CHECK(differ == 0);
    CHECK(std::equal(one.items().begin(), one.items().end(), many.items().begin()));
  }
}

TEMPLATE_TEST_CASE("BVH on threads: the wide tree is the same too", "[bvh]", float, double) {
  using T = TestType;
  const std::vector<Bounds<T>> boxes = scatteredBoxes<T>(5000, 3);
  const WideBvh<T> one(boxes, 1), many(boxes, 4);
  REQUIRE(many.nodes().size() == one.nodes().size());
  CHECK(std::equal(one.items().begin(), one.items().end(), many.items().begin()));
  int differ = 0;
  for (std::size_t n = 0; n < one.nodes().size(); ++n)
    if (std::memcmp(&one.nodes()[n], &many.nodes()[n], sizeof(one.nodes()[n])) != 0) ++differ;
  CHECK(differ == 0);
}
