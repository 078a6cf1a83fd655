// The 4- and 8-wide float BVHs against a brute-force loop over every box, tested the
// way the binary double walk tested them (SlabTest<double>): on thousands of
// random rays, rays lying in box faces and along box edges, axis-parallel
// rays with +0 and -0 direction components, and rays starting inside boxes,
// no box the brute force reaches may be culled, the nearest entry must be
// the brute force's, and extra boxes (the conservative rounding's) must lie
// within a hair of the ray (checked on the slab test itself, as a leaf's
// items share one lane). Also: the SSE and scalar slab tests agree bit for
// bit, and the depth bound holds on degenerate inputs.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <set>
#include <type_traits>

#include "render/accel/wide_bvh.hpp"

using namespace lattice;

namespace {

using Boxes = std::vector<Bounds<double>>;

// Random boxes of many sizes, some flat in one axis, some duplicated.
Boxes randomBoxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-10, 10), size(0.01, 1.5), unit(0, 1);
  Boxes boxes;
  for (int i = 0; i < n; ++i) {
    Vec3d lo(pos(rng), pos(rng), pos(rng)), ext(size(rng), size(rng), size(rng));
    if (unit(rng) < 0.05) ext[i % 3] = 0;  // flat
    boxes.push_back({lo, lo + ext});
    if (unit(rng) < 0.02) boxes.push_back(boxes.back());
  }
  return boxes;
}

template <typename T>
std::vector<Bounds<T>> asT(const Boxes& boxes) {
  std::vector<Bounds<T>> out;
  for (const auto& b : boxes) out.push_back({Vec3<T>(b.lo), Vec3<T>(b.hi)});
  return out;
}

struct TestRay {
  Vec3d origin, direction;
  double tmin, tmax;
};

// A mix of ray kinds; each comes back in T exactly (its double form is what
// the brute force uses).
template <typename T>
std::vector<TestRay> testRays(const std::vector<Bounds<T>>& boxes, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-12, 12), unit(0, 1), len(0.5, 40);
  std::uniform_int_distribution<std::size_t> pick(0, boxes.size() - 1);
  std::uniform_int_distribution<int> axisOf(0, 2);
  auto randomDir = [&] {
    Vec3d d(pos(rng), pos(rng), pos(rng));
    return d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  };
  auto corner = [&](const Bounds<T>& b, int bits) {
    return Vec3d(double((bits & 1) ? b.hi.x : b.lo.x), double((bits & 2) ? b.hi.y : b.lo.y),
                 double((bits & 4) ? b.hi.z : b.lo.z));
  };
  std::vector<TestRay> rays;
  for (int i = 0; i < n; ++i) {
    const Bounds<T>& b = boxes[pick(rng)];
    Vec3d o(pos(rng), pos(rng), pos(rng)), d = randomDir();
    double tmin = unit(rng) < 0.5 ? 0.0 : unit(rng), tmax = len(rng);
    switch (i % 6) {
      case 0: break;  // anywhere
      case 1: {       // in a face's plane, parallel to it
        int a = axisOf(rng);
        o[a] = double(unit(rng) < 0.5 ? b.lo[a] : b.hi[a]);
        d[a] = unit(rng) < 0.5 ? 0.0 : -0.0;
        break;
      }
      case 2: {  // along an edge line (two coordinates on the box's corner), axis-parallel
        int a = axisOf(rng);
        o = corner(b, static_cast<int>(rng() & 7u));
        o[a] = pos(rng);
        d = Vec3d(unit(rng) < 0.5 ? 0.0 : -0.0);
        d[a] = o[a] < double(b.lo[a]) ? 1.0 : -1.0;
        break;
      }
      case 3: {  // aimed at a corner from outside (grazes it up to rounding)
        Vec3d c = corner(b, static_cast<int>(rng() & 7u));
        o = c - d * (1 + 5 * unit(rng));
        break;
      }
      case 4: {  // starting inside a box
        o = Vec3d(double(b.lo.x) + unit(rng) * double(b.hi.x - b.lo.x), double(b.lo.y) + unit(rng) * double(b.hi.y - b.lo.y),
                  double(b.lo.z) + unit(rng) * double(b.hi.z - b.lo.z));
        break;
      }
      case 5: {  // axis-parallel from anywhere
        int a = axisOf(rng);
        d = Vec3d(0.0);
        d[a] = unit(rng) < 0.5 ? 1.0 : -1.0;
        break;
      }
    }
    // Round to T so both sides see the same ray.
    TestRay r{Vec3d(Vec3<T>(o)), Vec3d(Vec3<T>(d)), double(T(tmin)), double(T(tmax))};
    for (int a = 0; a < 3; ++a)
      if (d[a] == 0.0) r.direction[a] = d[a];  // keep the sign of zero
    rays.push_back(r);
  }
  return rays;
}

template <typename T>
Ray<T> toRay(const TestRay& r) {
  return {Vec3<T>(r.origin), Vec3<T>(r.direction)};
}

template <typename T>
T roundUp(double t) {
  if constexpr (std::is_same_v<T, float>) return floatAbove(t);
  else return t;
}

// The binary double walk's box test.
bool bruteHit(const Bounds<double>& b, const TestRay& r, double tmin, double tmax, double& t0) {
  const SlabTest<double> slab(Ray<double>{r.origin, r.direction});
  return slab.clip(b, tmin, tmax, t0);
}

// The same box and segment widened by a relative 1e-5: what a conservative
// float test may add.
bool nearHit(const Bounds<double>& b, const TestRay& r) {
  Bounds<double> w = b;
  for (int a = 0; a < 3; ++a) {
    double pad = 1e-5 * (1 + std::fabs(b.lo[a]) + std::fabs(b.hi[a]));
    w.lo[a] -= pad;
    w.hi[a] += pad;
  }
  double t0;
  return bruteHit(w, r, r.tmin - 1e-5 * (1 + std::fabs(r.tmin)), r.tmax + 1e-5 * (1 + std::fabs(r.tmax)), t0);
}

template <typename T>
void checkAgainstBruteForce(const Boxes& source, unsigned seed, WideForm form) {
  const std::vector<Bounds<T>> boxes = asT<T>(source);
  const WideBvh<T> bvh(boxes, form);
  Boxes exact;  // the boxes as T holds them, in double
  for (const auto& b : boxes) exact.push_back({Vec3d(b.lo), Vec3d(b.hi)});
  std::size_t bruteHits = 0, extras = 0, nearestFound = 0;
  for (const TestRay& r : testRays<T>(boxes, 6000, seed)) {
    const Ray<T> ray = toRay<T>(r);
    std::vector<std::uint32_t> want;
    double nearest = r.tmax;
    for (std::uint32_t n = 0; n < exact.size(); ++n) {
      double t0;
      if (bruteHit(exact[n], r, r.tmin, r.tmax, t0)) {
        want.push_back(n);
        nearest = std::min(nearest, t0);
      }
    }
    bruteHits += want.size();

    std::vector<std::uint32_t> got;
    CHECK_FALSE(bvh.visitAll(ray, T(r.tmin), T(r.tmax), [&](std::uint32_t item) {
      got.push_back(item);
      return false;
    }));
    std::sort(got.begin(), got.end());
    REQUIRE(std::adjacent_find(got.begin(), got.end()) == got.end());  // each item once
    // What a visitor testing each item's own box finds (as a union's
    // children do) is exactly the brute force's set. Other items come with
    // the leaves (up to four items share a lane's box).
    std::vector<std::uint32_t> found;
    for (std::uint32_t n : got) {
      double t0;
      if (bruteHit(exact[n], r, r.tmin, r.tmax, t0)) found.push_back(n);
    }
    REQUIRE(found == want);
    extras += got.size() - found.size();

    // Any hit: stops at the first item, and only when there is one.
    REQUIRE(bvh.visitAll(ray, T(r.tmin), T(r.tmax), [&](std::uint32_t item) {
      double t0;
      return bruteHit(exact[item], r, r.tmin, r.tmax, t0);
    }) == !want.empty());

    // Nearest first: the visitor lowers the limit to each box's entry, as
    // a union lowers it to each child's hit; the nearest must be found.
    T limit = T(r.tmax);
    double best = r.tmax;
    bvh.visitFrontToBack(ray, T(r.tmin), limit, [&](std::uint32_t item, T& lim) {
      double t0;
      if (bruteHit(exact[item], r, r.tmin, double(lim), t0) && t0 < double(lim)) {
        best = std::min(best, t0);
        lim = roundUp<T>(t0);  // at tmin (a ray starting inside) it stops the walk: nothing is nearer
      }
    });
    if (!want.empty() && nearest < r.tmax) {
      REQUIRE(best == nearest);
      ++nearestFound;
    }
  }
  INFO("brute-force hits " << bruteHits << ", extra items visited " << extras);
  REQUIRE(bruteHits > 10000);
  REQUIRE(nearestFound > 2000);
}

}  // namespace

TEMPLATE_TEST_CASE("the wide BVH visits every box a brute-force loop hits, on random and grazing rays", "[bvh]", float,
                   double) {
  for (WideForm form : {WideForm::Four, WideForm::Eight}) checkAgainstBruteForce<TestType>(randomBoxes(3000, 3), 11, form);
}

TEMPLATE_TEST_CASE("the wide BVH loses no box of hair-like long thin boxes", "[bvh]", float, double) {
  // Long thin diagonal boxes radiating from a sphere, as a lattice_scatter's hairs are.
  std::mt19937 rng(8);
  std::normal_distribution<double> g(0, 1);
  Boxes boxes;
  for (int i = 0; i < 2000; ++i) {
    Vec3d d(g(rng), g(rng), g(rng));
    d /= std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    Vec3d a = d * 3.0, b = d * 4.5;
    boxes.push_back({componentMin(a, b) - 0.02, componentMax(a, b) + 0.02});
  }
  for (WideForm form : {WideForm::Four, WideForm::Eight}) checkAgainstBruteForce<TestType>(boxes, 12, form);
}

// Every lane's box holds its subtree's item boxes, and each item is reached once.
template <typename T, typename NodeT>
void checkLanes(const WideBvh<T>& bvh, const std::vector<NodeT>& nodes, const std::vector<Bounds<T>>& boxes) {
  REQUIRE(!nodes.empty());
  std::multiset<std::uint32_t> items(bvh.items().begin(), bvh.items().end());
  REQUIRE(items.size() == boxes.size());
  std::size_t reached = 0;
  std::function<void(std::uint32_t)> check = [&](std::uint32_t index) {
    const auto& node = nodes[index];
    REQUIRE(node.used != 0);
    for (int lane = 0; lane < NodeT::kLanes; ++lane) {
      if (!(node.used & (1u << lane))) continue;
      auto inside = [&](const Bounds<T>& b) {
        for (int a = 0; a < 3; ++a) {
          REQUIRE(double(node.lanes.box[0][a][lane]) <= double(b.lo[a]));
          REQUIRE(double(node.lanes.box[1][a][lane]) >= double(b.hi[a]));
        }
      };
      if (node.count[lane] > 0) {
        REQUIRE(node.count[lane] <= 4);  // one leaf cull pass
        for (std::uint32_t n = 0; n < node.count[lane]; ++n) inside(boxes[bvh.items()[node.ref[lane] + n]]);
        reached += node.count[lane];
      } else {
        REQUIRE(node.ref[lane] > index);
        check(node.ref[lane]);
      }
    }
  };
  check(0);
  REQUIRE(reached == boxes.size());
  REQUIRE(bvh.depth() <= bvh.binaryDepth());
  REQUIRE(bvh.depth() < 20);  // 3000 boxes: a wide log-depth tree, not a list
}

TEMPLATE_TEST_CASE("wide BVH lanes hold their items' boxes rounded outwards, each item once", "[bvh]", float, double) {
  using T = TestType;
  const std::vector<Bounds<T>> boxes = asT<T>(randomBoxes(3000, 5));
  const WideBvh<T> four(boxes, WideForm::Four);
  REQUIRE(four.form() == WideForm::Four);
  checkLanes(four, four.nodes(), boxes);
#if LATTICE_WIDE8
  if (!eightWideRuns()) {
    WARN("skipped: this CPU has no AVX2, so no 8-wide tree is built");
    return;
  }
  const WideBvh<T> eight(boxes, WideForm::Eight), culled(boxes, WideForm::Eight, LeafItems::Culled);
  REQUIRE(eight.form() == WideForm::Eight);
  REQUIRE(eight.nodes().empty());
  checkLanes(eight, eight.nodes8(), boxes);
  checkLanes(culled, culled.nodes8(), boxes);
  REQUIRE(eight.depth() <= four.depth());
  REQUIRE(eight.nodes8().size() < four.nodes().size());
  // Leaf lanes: the binary leaves, or (culled) whole subtrees of up to four.
  const auto leafLanes = [](const auto& nodes) {
    std::size_t lanes = 0;
    for (const auto& node : nodes)
      for (int lane = 0; lane < 8; ++lane) lanes += (node.used >> lane & 1u) && node.count[lane] > 0;
    return lanes;
  };
  std::size_t binaryLeaves = 0;
  const Bvh<T> binary(boxes);  // named: a range-for over a temporary's nodes() would read freed nodes
  for (const auto& node : binary.nodes()) binaryLeaves += node.count > 0;
  REQUIRE(leafLanes(eight.nodes8()) == binaryLeaves);
  REQUIRE(leafLanes(culled.nodes8()) < binaryLeaves * 3 / 4);
#endif
}

TEMPLATE_TEST_CASE("the wide BVH's depth bound holds on degenerate inputs", "[bvh]", float, double) {
  using T = TestType;
  const int n = 20000;
  std::vector<Bounds<T>> equal(n, Bounds<T>{Vec3<T>(T(1)), Vec3<T>(T(2))});
  std::vector<Bounds<T>> line, point, spread;
  for (int i = 0; i < n; ++i) {
    line.push_back({Vec3<T>(T(i), T(0), T(0)), Vec3<T>(T(i + 1), T(1), T(1))});  // touching, in a row
    point.push_back({Vec3<T>(T(0)), Vec3<T>(T(0))});                            // zero volume, all equal
  }
  // Spaced exponentially along x (1 to 1e85: double only): each split peels a
  // few off, so the depth cap leaves hundreds of items in one leaf.
  if constexpr (std::is_same_v<T, double>)
    for (int i = 0; i < 1500; ++i) {
      const double x = std::pow(1.3, i * 0.5);
      spread.push_back({Vec3<T>(T(x), T(0), T(0)), Vec3<T>(T(x * 1.01), T(1), T(1))});
    }
  for (const auto* boxes : {&equal, &line, &point, &spread})
  for (WideForm form : {WideForm::Four, WideForm::Eight}) {
    if (boxes->empty()) continue;
    const WideBvh<T> bvh(*boxes, form);
    // The stack holds at most (lanes - 1) * depth + 1 entries.
    REQUIRE(bvh.depth() <= bvh.binaryDepth());
    REQUIRE(bvh.binaryDepth() <= Bvh<T>::kMaxDepth);
    REQUIRE(3 * bvh.depth() + 1 <= WideBvh<T>::kStack);
    REQUIRE(7 * bvh.depth() + 1 <= WideBvh<T>::kStack8);
    if (boxes != &spread) REQUIRE(bvh.depth() <= 2 * int(std::ceil(std::log2(double(n)))));
    if (boxes == &spread) {
      std::uint32_t largest = 0;
      const Bvh<T> binary(spread);  // named, as above
      for (const auto& node : binary.nodes()) largest = std::max(largest, node.count);
      REQUIRE(largest > 255);  // more than a byte counts
    }
    // A ray through every box visits each exactly once, in either walk.
    const Ray<T> ray{Vec3<T>(T(-1), T(0.5), T(0.5)), Vec3<T>(T(1), T(0), T(0))};
    const Ray<T> diag{Vec3<T>(T(-1)), Vec3<T>(T(1))};
    const Ray<T>& r = boxes == &line || boxes == &spread ? ray : diag;
    std::vector<int> seen(boxes->size(), 0);
    const T far = boxes == &spread ? T(1e300) : T(1e9);
    bvh.visitAll(r, T(0), far, [&](std::uint32_t item) {
      ++seen[item];
      return false;
    });
    REQUIRE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    T limit = far;
    std::fill(seen.begin(), seen.end(), 0);
    bvh.visitFrontToBack(r, T(0), limit, [&](std::uint32_t item, T&) { ++seen[item]; });
    REQUIRE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
  }
}

TEST_CASE("the slab test keeps every box the double test hits, only boxes near the ray, the same in SSE and scalar", "[bvh]") {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> pos(-10, 10), unit(0, 1);
  int kept = 0;
  for (int i = 0; i < 20000; ++i) {
    BoxLanes lanes;
    for (int lane = 0; lane < 4; ++lane)
      for (int a = 0; a < 3; ++a) {
        double x = pos(rng), y = x + (unit(rng) < 0.1 ? 0.0 : 3 * unit(rng));
        lanes.box[0][a][lane] = floatBelow(x);
        lanes.box[1][a][lane] = floatAbove(y);
      }
    Vec3d o(pos(rng), pos(rng), pos(rng)), d(pos(rng), pos(rng), pos(rng));
    const int axis = i % 5 % 3;
    if (i % 3 == 0) {
      o[axis] = double(lanes.box[i % 2][axis][i % 4]);  // in a face's plane
      d[axis] = (i % 2) ? 0.0 : -0.0;
    }
    const WideRay wray(Ray<double>{o, d});
    const float tmin = floatBelow(unit(rng) * 0.1), limit = floatAbove(unit(rng) < 0.1 ? 1e30 : 5 * unit(rng));
    float entry[4];
    const unsigned mask = slabTest4Scalar(lanes, wray, tmin, limit, entry);
#if defined(__SSE2__)
    float sseEntry[4];
    REQUIRE(slabTest4Sse(lanes, wray, tmin, limit, sseEntry) == mask);
    REQUIRE(std::memcmp(entry, sseEntry, sizeof entry) == 0);
#endif
    kept += __builtin_popcount(mask);
    const TestRay r{o, d, double(tmin), double(limit)};
    for (int lane = 0; lane < 4; ++lane) {
      Bounds<double> b;
      for (int a = 0; a < 3; ++a) {
        b.lo[a] = lanes.box[0][a][lane];
        b.hi[a] = lanes.box[1][a][lane];
      }
      double t0;
      const bool exactHit = bruteHit(b, r, r.tmin, r.tmax, t0), keep = (mask >> lane) & 1u;
      if (exactHit) {
        REQUIRE(keep);
        REQUIRE(double(entry[lane]) <= t0);  // a lower bound of the entry
      }
      INFO("i " << i << " lane " << lane << " o " << o.x << " " << o.y << " " << o.z << " d " << d.x << " " << d.y << " " << d.z
                << " box " << b.lo.x << " " << b.lo.y << " " << b.lo.z << " / " << b.hi.x << " " << b.hi.y << " " << b.hi.z
                << " t " << tmin << " " << limit << " entry " << entry[lane]);
      if (keep && !exactHit) REQUIRE(nearHit(b, r));
    }
  }
  REQUIRE(kept > 300);
}

TEST_CASE("float rounding of box corners is directed", "[bvh]") {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> v(-1e6, 1e6);
  for (int i = 0; i < 10000; ++i) {
    double x = v(rng) * std::pow(10.0, double(i % 13) - 6.0);
    REQUIRE(double(floatBelow(x)) <= x);
    REQUIRE(double(floatAbove(x)) >= x);
    REQUIRE(std::nextafter(floatBelow(x), std::numeric_limits<float>::infinity()) >= floatAbove(x));
  }
  REQUIRE(floatAbove(1e300) == std::numeric_limits<float>::infinity());
  REQUIRE(floatBelow(1e300) == std::numeric_limits<float>::max());
  REQUIRE(floatBelow(-1e300) == -std::numeric_limits<float>::infinity());
  REQUIRE(floatBelow(0.0) == 0.0f);
  REQUIRE(double(floatBelow(1e-50)) == 0.0);
  REQUIRE(floatAbove(1e-50) == std::numeric_limits<float>::denorm_min());
}
