// The BVH built on threads (render/accel/bvh.cpp: the two subtrees of the top
// splits at once) is the tree the one-thread build makes, node for node.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <random>
#include <vector>

#include "foundation/fixed.hpp"
#include "render/accel/bvh.hpp"
#include "render/accel/wide_bvh.hpp"
#include "scattered_boxes.hpp"

using namespace lattice;

using lattice::testing::scatteredBoxes;

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

// Both wide forms and both leaf groupings: the 8-wide one exists where the CPU has AVX2.
template <typename Nodes>
int differingNodes(const Nodes& one, const Nodes& many) {
  REQUIRE(many.size() == one.size());
  int differ = 0;
  for (std::size_t n = 0; n < one.size(); ++n)
    if (std::memcmp(&one[n].lanes, &many[n].lanes, sizeof(one[n].lanes)) != 0 ||  // field by field: no padding compared
        !std::equal(std::begin(one[n].ref), std::end(one[n].ref), std::begin(many[n].ref)) ||
        !std::equal(std::begin(one[n].count), std::end(one[n].count), std::begin(many[n].count)) ||
        one[n].used != many[n].used)
      ++differ;
  return differ;
}

TEMPLATE_TEST_CASE("BVH on threads: the wide tree is the same too", "[bvh]", float, double) {
  using T = TestType;
  const std::vector<Bounds<T>> boxes = scatteredBoxes<T>(5000, 3);
  for (WideForm form : {WideForm::Four, WideForm::Eight})
    for (LeafItems leaves : {LeafItems::Visited, LeafItems::Culled}) {
      const WideBvh<T> one(boxes, form, leaves, 1), many(boxes, form, leaves, 4);
      REQUIRE(one.form() == many.form());
      CHECK(std::equal(one.items().begin(), one.items().end(), many.items().begin()));
      CHECK(differingNodes(one.nodes(), many.nodes()) == 0);
#if LATTICE_WIDE8
      CHECK(differingNodes(one.nodes8(), many.nodes8()) == 0);
#endif
    }
}
