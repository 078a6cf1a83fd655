// The 8-wide BVH (AVX2) against the 4-wide one it stands in for: a union's
// questions asked of both on random rays must get the same answers (the
// nearest enter's item and distance, any hit, the set of items whose own box
// the ray meets). Where two items enter at exactly the same distance (the
// duplicated boxes here) the first visited wins, and which that is depends on
// how the binary tree's nodes are grouped (the 4-wide walk differs from the
// binary one there too): the 8-wide winner must then be one of the tied
// items, and the test counts how often it is not the 4-wide one's. Also: the
// AVX slab test and the AVX set-up of a ray agree bit for bit with the scalar
// references, and the run-time choice of the width falls back to four lanes
// when asked to or when the CPU has no AVX2 (checked against /proc/cpuinfo).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>

#include "render/accel/wide_bvh.hpp"

using namespace lattice;

namespace {

// Random boxes of many sizes, some flat, some duplicated, some sharing a face.
std::vector<Bounds<double>> randomBoxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-10, 10), size(0.01, 1.5), unit(0, 1);
  std::vector<Bounds<double>> boxes;
  for (int i = 0; i < n; ++i) {
    Vec3d lo(pos(rng), pos(rng), pos(rng)), ext(size(rng), size(rng), size(rng));
    if (unit(rng) < 0.05) ext[i % 3] = 0;
    if (unit(rng) < 0.05 && !boxes.empty()) lo = boxes.back().lo;  // the same entry face as the last
    boxes.push_back({lo, lo + ext});
    if (unit(rng) < 0.05) boxes.push_back(boxes.back());
  }
  return boxes;
}

template <typename T>
std::vector<Bounds<T>> asT(const std::vector<Bounds<double>>& boxes) {
  std::vector<Bounds<T>> out;
  for (const auto& b : boxes) out.push_back({Vec3<T>(b.lo), Vec3<T>(b.hi)});
  return out;
}

// What a union asks, with each item answering by its own box (exact double
// slab test), as a child answers by its surface.
struct Answers {
  std::uint32_t nearestItem = ~0u;
  double nearestT = 0;
  bool any = false;
  std::vector<std::uint32_t> met;  // sorted
};

template <typename T>
Answers ask(const WideBvh<T>& bvh, const std::vector<Bounds<T>>& boxes, const Ray<T>& ray, T tmin, T tmax) {
  const SlabTest<double> slab(Ray<double>{Vec3d(ray.origin), Vec3d(ray.direction)});
  auto entry = [&](std::uint32_t item, double lo, double hi, double& t) {
    const Bounds<double> b{Vec3d(boxes[item].lo), Vec3d(boxes[item].hi)};
    return slab.clip(b, lo, hi, t);
  };
  Answers a;
  T limit = tmax;
  // A union's first enter: an item answers only strictly before the limit, so
  // on a tie the item visited first wins.
  bvh.visitFrontToBack(ray, tmin, limit, [&](std::uint32_t item, T& lim) {
    double t;
    if (entry(item, double(tmin), double(lim), t) && T(t) < lim && T(t) > tmin) {
      lim = T(t);
      a.nearestItem = item;
      a.nearestT = double(lim);
    }
  });
  a.any = bvh.visitAll(ray, tmin, tmax, [&](std::uint32_t item) {
    double t;
    return entry(item, double(tmin), double(tmax), t);
  });
  bvh.visitAll(ray, tmin, tmax, [&](std::uint32_t item) {
    double t;
    if (entry(item, double(tmin), double(tmax), t)) a.met.push_back(item);
    return false;
  });
  std::sort(a.met.begin(), a.met.end());
  return a;
}

template <typename T>
void compareForms(unsigned seed, LeafItems leaves) {
  const std::vector<Bounds<T>> boxes = asT<T>(randomBoxes(4000, seed));
  const WideBvh<T> four(boxes, WideForm::Four), eight(boxes, WideForm::Eight, leaves);
  REQUIRE(four.form() == WideForm::Four);
  REQUIRE(eight.form() == WideForm::Eight);
  std::mt19937 rng(seed + 100);
  std::uniform_real_distribution<double> pos(-14, 14), unit(0, 1);
  std::uniform_int_distribution<std::size_t> pick(0, boxes.size() - 1);
  int nearest = 0, ties = 0, otherWinner = 0;
  for (int i = 0; i < 20000; ++i) {
    // Aimed at a box's corner or centre, or axis-parallel, or from inside a box.
    const Bounds<T>& target = boxes[pick(rng)];
    Vec3d o(pos(rng), pos(rng), pos(rng)), at = (Vec3d(target.lo) + Vec3d(target.hi)) * 0.5;
    if (i % 5 == 1) at = Vec3d(target.lo);
    if (i % 5 == 2) o = at + Vec3d(0.01, 0.02, -0.01);
    Vec3d d = at - o;
    if (i % 5 == 3) d = Vec3d(0, 0, 0), d[i % 3] = unit(rng) < 0.5 ? 1.0 : -1.0, o[i % 3] = -20.0 * d[i % 3];
    const Ray<T> ray{Vec3<T>(o), Vec3<T>(d)};
    const T tmin = T(i % 7 == 0 ? 0.5 : 1e-4), tmax = T(i % 11 == 0 ? 0.8 : 1e30);
    const Answers a4 = ask(four, boxes, ray, tmin, tmax), a8 = ask(eight, boxes, ray, tmin, tmax);
    INFO("ray " << i << " nearest " << a4.nearestItem << " / " << a8.nearestItem);
    REQUIRE(a8.nearestT == a4.nearestT);
    REQUIRE(a8.any == a4.any);
    REQUIRE(a8.met == a4.met);
    if (a4.nearestItem == ~0u) {
      REQUIRE(a8.nearestItem == ~0u);
      continue;
    }
    ++nearest;
    // The items entering at the nearest distance (the winner among them).
    const SlabTest<double> s(Ray<double>{Vec3d(ray.origin), Vec3d(ray.direction)});
    std::vector<std::uint32_t> tied;
    for (std::uint32_t item : a4.met) {
      double t;
      if (s.clip(Bounds<double>{Vec3d(boxes[item].lo), Vec3d(boxes[item].hi)}, double(tmin), double(tmax), t) &&
          double(T(t)) == a4.nearestT)
        tied.push_back(item);
    }
    REQUIRE(std::find(tied.begin(), tied.end(), a4.nearestItem) != tied.end());
    if (tied.size() == 1) {
      REQUIRE(a8.nearestItem == a4.nearestItem);
    } else {
      ++ties;
      REQUIRE(std::find(tied.begin(), tied.end(), a8.nearestItem) != tied.end());
      if (a8.nearestItem != a4.nearestItem) ++otherWinner;
    }
  }
  WARN("rays with a nearest item " << nearest << ", with an exact tie for it " << ties << ", of which "
                                   << otherWinner << " won by another of the tied items");
  REQUIRE(nearest > 10000);
  REQUIRE(ties > 50);  // the duplicated boxes put ties to the test
}

bool cpuinfoSaysAvx2() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("flags", 0) != 0) continue;
    std::istringstream words(line);
    std::string w;
    while (words >> w)
      if (w == "avx2") return true;
    return false;
  }
  return false;
}

}  // namespace

TEMPLATE_TEST_CASE("the 8-wide BVH reports the 4-wide one's items on random rays", "[bvh]", float,
                   double) {
  if (!eightWideRuns()) {
    WARN("skipped: this CPU has no AVX2, so no 8-wide tree is built");
    return;
  }
  compareForms<TestType>(31, LeafItems::Visited);
  compareForms<TestType>(32, LeafItems::Culled);
}

TEST_CASE("the width is chosen at run time and falls back to four lanes", "[bvh]") {
  const std::vector<Bounds<double>> boxes = randomBoxes(500, 7);
#if defined(__x86_64__) && defined(__linux__)
  REQUIRE(eightWideRuns() == cpuinfoSaysAvx2());  // the CPU's own word
#endif
  REQUIRE(resolveWideForm(WideForm::Four) == WideForm::Four);
  REQUIRE(resolveWideForm(WideForm::Eight) == (eightWideRuns() ? WideForm::Eight : WideForm::Four));
  REQUIRE(WideBvh<double>(boxes, WideForm::Four).form() == WideForm::Four);
  REQUIRE(WideBvh<double>(boxes, WideForm::Eight).form() == resolveWideForm(WideForm::Eight));

  setWideForm(WideForm::Four);  // what a CPU without AVX2 gets, forced
  const WideBvh<double> forced(boxes);
  setWideForm(WideForm::Auto);
  REQUIRE(forced.form() == WideForm::Four);
  REQUIRE(!forced.nodes().empty());
  const WideBvh<double> chosen(boxes);
  REQUIRE(chosen.form() == (eightWideRuns() ? WideForm::Eight : WideForm::Four));
  // Either answers (the items whose own box the ray meets): the walk follows
  // the form the tree was built in.
  const Ray<double> ray{Vec3d(-20, 0.1, 0.2), (boxes[3].lo + boxes[3].hi) * 0.5 - Vec3d(-20, 0.1, 0.2)};
  const SlabTest<double> slab(ray);
  std::vector<std::uint32_t> a, b;
  auto metBy = [&](std::vector<std::uint32_t>& met) {
    return [&](std::uint32_t item) {
      double t;
      if (slab.clip(boxes[item], 0.0, 1e9, t)) met.push_back(item);
      return false;
    };
  };
  forced.visitAll(ray, 0.0, 1e9, metBy(a));
  chosen.visitAll(ray, 0.0, 1e9, metBy(b));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  REQUIRE(!a.empty());
  REQUIRE(a == b);
}

#if LATTICE_WIDE8
namespace {
// The AVX test is always inlined and needs its target in the caller.
__attribute__((target("avx2"))) unsigned slabTest8(const BoxLanes8& b, const WideRay& r, float tmin, float limit,
                                                   float entry[8]) {
  return slabTest8Avx2(b, r, tmin, limit, entry);
}
template <typename T>
__attribute__((target("avx2"))) WideRay wideRay8(const Ray<T>& ray) {
  return wideRayAvx2(ray);
}

// Every field of the AVX set-up equals the scalar constructor's, bit for bit.
template <typename T>
void checkWideRays() {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> pos(-10, 10), unit(0, 1);
  std::uniform_int_distribution<int> exponent(-160, 130);  // below float subnormals to beyond float range
  int rounded = 0;
  for (int i = 0; i < 50000; ++i) {
    Vec3d o, d;
    for (int a = 0; a < 3; ++a) {
      o[a] = pos(rng) * std::ldexp(1.0, i % 7 == 0 ? exponent(rng) : 0);
      d[a] = pos(rng) * std::ldexp(1.0, i % 5 == 0 ? exponent(rng) : 0);
      if (i % 9 == a) d[a] = unit(rng) < 0.5 ? 0.0 : -0.0;
      if (i % 11 == a) o[a] = unit(rng) < 0.5 ? 0.0 : -0.0;
      if (i % 13 == a) o[a] = double(float(o[a]));  // exactly a float
    }
    const Ray<T> ray{Vec3<T>(o), Vec3<T>(d)};
    const WideRay scalar(ray), lanes = wideRay8(ray);
    INFO("ray " << i);
    REQUIRE(std::memcmp(scalar.inverse, lanes.inverse, sizeof scalar.inverse) == 0);
    REQUIRE(std::memcmp(scalar.originNear, lanes.originNear, sizeof scalar.originNear) == 0);
    REQUIRE(std::memcmp(scalar.originFar, lanes.originFar, sizeof scalar.originFar) == 0);
    REQUIRE(std::memcmp(scalar.nearSide, lanes.nearSide, sizeof scalar.nearSide) == 0);
    for (int a = 0; a < 3; ++a) rounded += scalar.originNear[a] != scalar.originFar[a];
  }
  if constexpr (std::is_same_v<T, double>) REQUIRE(rounded > 50000);  // the outward steps were taken
}
}  // namespace

TEMPLATE_TEST_CASE("the AVX set-up of a ray is the scalar one's, bit for bit", "[bvh]", float, double) {
  if (!eightWideRuns()) {
    WARN("skipped: this CPU has no AVX2");
    return;
  }
  checkWideRays<TestType>();
}

TEST_CASE("the AVX slab test of eight boxes is the scalar reference's, bit for bit", "[bvh]") {
  if (!eightWideRuns()) {
    WARN("skipped: this CPU has no AVX2");
    return;
  }
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> pos(-10, 10), unit(0, 1);
  int kept = 0;
  for (int i = 0; i < 20000; ++i) {
    BoxLanes8 lanes;
    for (int lane = 0; lane < 8; ++lane)
      for (int a = 0; a < 3; ++a) {
        double x = pos(rng), y = x + (unit(rng) < 0.1 ? 0.0 : 3 * unit(rng));
        lanes.box[0][a][lane] = floatBelow(x);
        lanes.box[1][a][lane] = floatAbove(y);
      }
    Vec3d o(pos(rng), pos(rng), pos(rng)), d(pos(rng), pos(rng), pos(rng));
    if (i % 4 == 0) d[i % 3] = (i % 8 == 0) ? 0.0 : -0.0;  // a zero component of either sign
    if (i % 6 == 0) o[i % 3] = double(lanes.box[0][i % 3][i % 8]);  // in a face's plane
    const float tmin = i % 3 == 0 ? -1.0f : 0.0f, limit = i % 5 == 0 ? 0.5f : 1e30f;
    const WideRay wray(Ray<double>{o, d});
    float scalarEntry[8], avxEntry[8];
    const unsigned mask = slabTestScalar<8>(lanes.box, wray, tmin, limit, scalarEntry);
    REQUIRE(slabTest8(lanes, wray, tmin, limit, avxEntry) == mask);
    REQUIRE(std::memcmp(scalarEntry, avxEntry, sizeof scalarEntry) == 0);
    kept += __builtin_popcount(mask);
  }
  REQUIRE(kept > 300);
}
#endif
