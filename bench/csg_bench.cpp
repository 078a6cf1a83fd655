// Cost per ray of a union of N random spheres, through the union node's BVH
// versus a flat loop over the children, N = 10 .. 10000. Prints a table of
// median nanoseconds per ray (first hit and any hit) for docs/geometry.md.
//
// Usage: csg_bench [repetitions]   (default 7; the median is reported)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <time.h>
#include <vector>

#include "render/shapes/csg.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;

namespace {

// Forwards to a leaf and counts how often the union asks it anything: the
// algorithmic cost per ray, free of the timing noise of a shared machine.
template <typename T>
class Counted final : public Primitive<T> {
 public:
  Counted(PrimitivePtr<T> inner, long& counter) : inner_(std::move(inner)), counter_(counter) {}
  const Bounds<T>& bounds() const override { return inner_->bounds(); }
  void spans(const Ray<T>& ray, T tmin, T tmax, SpanList<T>& out) const override {
    ++counter_;
    inner_->spans(ray, tmin, tmax, out);
  }
  bool firstHit(const Ray<T>& ray, T tmin, T tmax, Hit<T>& hit) const override {
    ++counter_;
    return inner_->firstHit(ray, tmin, tmax, hit);
  }
  bool anyHit(const Ray<T>& ray, T tmin, T tmax) const override {
    ++counter_;
    return inner_->anyHit(ray, tmin, tmax);
  }

 private:
  PrimitivePtr<T> inner_;
  long& counter_;
};

template <typename T>
struct Setup {
  std::vector<PrimitivePtr<T>> flat;
  PrimitivePtr<T> bvhUnion;
  PrimitivePtr<T> countedUnion;  // the same union with counting leaves
  long leafCalls = 0;
  std::vector<Ray<T>> rays;
};

// Spheres fill a 20-unit cube; their radius shrinks like N^(-1/3) so the
// cube's fill (and so how far a ray travels before a hit) stays similar.
template <typename T>
std::unique_ptr<Setup<T>> makeSetup(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-10, 10), unit(-1, 1);
  const double radius = 3.0 * std::cbrt(10.0 / n);
  auto holder = std::make_unique<Setup<T>>();  // on the heap: the counters are referenced
  Setup<T>& s = *holder;
  std::vector<PrimitivePtr<T>> children, counted;
  for (int i = 0; i < n; ++i) {
    Vec3d c(pos(rng), pos(rng), pos(rng));
    QuarticShape b = sphere(radius * (0.5 + 0.5 * (unit(rng) + 1) / 2));
    Mat4d m = glm::translate(Mat4d(1), c);
    s.flat.push_back(makeQuarticLeaf<T>(b.f, b.bounds, m, MaterialId(i)));
    children.push_back(makeQuarticLeaf<T>(b.f, b.bounds, m, MaterialId(i)));
    counted.push_back(std::make_unique<Counted<T>>(makeQuarticLeaf<T>(b.f, b.bounds, m, MaterialId(i)), s.leafCalls));
  }
  s.bvhUnion = makeCsgNode<T>(CsgOp::Union, std::move(children));
  s.countedUnion = makeCsgNode<T>(CsgOp::Union, std::move(counted));
  // Camera-like rays: from a point outside the cube towards a random point in it.
  for (int i = 0; i < 4000; ++i) {
    Vec3d o(0, 0, -40);
    Vec3d target(pos(rng), pos(rng), pos(rng));
    s.rays.push_back({Vec3<T>(o), Vec3<T>(glm::normalize(target - o))});
  }
  return holder;
}

// Naive union first hit: every child whose box the ray meets.
template <typename T>
bool flatFirstHit(const std::vector<PrimitivePtr<T>>& children, const Ray<T>& ray, T tmax, Hit<T>& hit) {
  bool found = false;
  for (const auto& c : children) {
    T t0, t1;
    if (!c->bounds().clip(ray, T(0), tmax, t0, t1)) continue;
    if (c->firstHit(ray, T(0), tmax, hit)) {
      tmax = hit.t;
      found = true;
    }
  }
  return found;
}

// CPU time of this thread: on a shared machine wall time would also count
// the time slices other processes get while a sample runs.
double threadCpuNs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

template <typename F>
double medianNsPerRay(int repetitions, std::size_t rays, F&& run) {
  std::vector<double> samples;
  for (int r = 0; r < repetitions; ++r) {
    double start = threadCpuNs();
    run();
    samples.push_back((threadCpuNs() - start) / double(rays));
  }
  std::sort(samples.begin(), samples.end());
  return samples[samples.size() / 2];
}

volatile double g_sink;  // keeps the measured work from being optimised away

template <typename T>
void row(int n, int repetitions) {
  std::unique_ptr<Setup<T>> holder = makeSetup<T>(n, 1234u + unsigned(n));
  Setup<T>& s = *holder;
  const T inf = std::numeric_limits<T>::infinity();
  std::size_t agree = 0;
  double bvhFirst = medianNsPerRay(repetitions, s.rays.size(), [&] {
    double sum = 0;
    for (const auto& ray : s.rays) {
      Hit<T> h;
      if (s.bvhUnion->firstHit(ray, T(0), inf, h)) sum += double(h.t);
    }
    g_sink = sum;
  });
  double bvhAny = medianNsPerRay(repetitions, s.rays.size(), [&] {
    double sum = 0;
    for (const auto& ray : s.rays) sum += s.bvhUnion->anyHit(ray, T(0), inf) ? 1 : 0;
    g_sink = sum;
  });
  // The flat loop is slow at large N: fewer repetitions keep the run short.
  double flat = medianNsPerRay(n >= 3000 ? 3 : repetitions, s.rays.size(), [&] {
    double sum = 0;
    for (const auto& ray : s.rays) {
      Hit<T> h;
      if (flatFirstHit(s.flat, ray, inf, h)) sum += double(h.t);
    }
    g_sink = sum;
  });
  // Same answers both ways (a benchmark of a wrong result is worthless).
  for (const auto& ray : s.rays) {
    Hit<T> a, b;
    bool ha = s.bvhUnion->firstHit(ray, T(0), inf, a), hb = flatFirstHit(s.flat, ray, inf, b);
    if (ha == hb && (!ha || a.t == b.t)) ++agree;
  }
  s.leafCalls = 0;
  for (const auto& ray : s.rays) {
    Hit<T> h;
    s.countedUnion->firstHit(ray, T(0), inf, h);
  }
  double leavesFirst = double(s.leafCalls) / double(s.rays.size());
  s.leafCalls = 0;
  for (const auto& ray : s.rays) s.countedUnion->anyHit(ray, T(0), inf);
  double leavesAny = double(s.leafCalls) / double(s.rays.size());
  // The flat loop's count: children whose box the ray meets.
  double leavesFlat = 0;
  for (const auto& ray : s.rays)
    for (const auto& c : s.flat) {
      T t0, t1;
      if (c->bounds().clip(ray, T(0), inf, t0, t1)) ++leavesFlat;
    }
  leavesFlat /= double(s.rays.size());
  fmt::print("| {} | {} | {:.0f} | {:.0f} | {:.0f} | {:.1f} | {:.1f} / {:.1f} / {:.1f} | {}/{} |\n", n,
             sizeof(T) == 4 ? "float" : "double", bvhFirst, bvhAny, flat, flat / bvhFirst, leavesFirst, leavesAny,
             leavesFlat, agree, s.rays.size());
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = argc > 1 ? std::atoi(argv[1]) : 7;
  if (repetitions < 1) {
    std::fprintf(stderr, "csg_bench: repetitions must be a positive integer\n");
    return 2;
  }
  fmt::print("median thread-CPU ns per ray, {} rays per sample, {} repetitions\n\n", 4000, repetitions);
  fmt::print("| N | scalar | BVH firstHit ns | BVH anyHit ns | flat firstHit ns | flat/BVH | leaves asked per ray: "
             "BVH first / BVH any / flat | agree |\n|---|---|---|---|---|---|---|---|\n");
  for (int n : {10, 30, 100, 300, 1000, 3000, 10000}) {
    row<float>(n, repetitions);
    row<double>(n, repetitions);
  }
  return 0;
}
