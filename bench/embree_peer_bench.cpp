// Peer benchmark: Lattice's CSG union (with its BVH) against Intel Embree 3
// (Debian's libembree-dev) on the same job — first hits of a grid of primary
// rays on N random spheres. Both run single-threaded in the same process,
// side by side, and the hits are cross-checked so the speed figure compares
// like with like. Lattice solves each sphere as a general quartic leaf
// (degree-2 polynomial in t through the quartic substitution), Embree uses its
// specialised sphere primitive: the ratio is the price of generality.
//
// Usage: embree_peer_bench [--spheres N ...] [--size W] [--runs R]
#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <ctime>
#include <vector>

#include "render/shapes/csg.hpp"
#include "render/shapes/quartic.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;

namespace {

struct SphereSet {
  std::vector<Vec3d> centres;
  double radius = 0;
};

SphereSet randomSpheres(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SphereSet set;
  // Keep total cross-section roughly constant so hit rates stay comparable as N grows.
  set.radius = 0.6 / std::sqrt(static_cast<double>(n));
  for (int i = 0; i < n; ++i) set.centres.push_back({u(rng), u(rng), u(rng)});
  return set;
}

Ray<double> primaryRay(int x, int y, int size) {
  double px = (x + 0.5) / size * 2.4 - 1.2, py = (y + 0.5) / size * 2.4 - 1.2;
  Vec3d origin(0, 0, -5);
  return {origin, Vec3d(px, py, 0) - Vec3d(0, 0, -1.5)};
}

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

struct Medians {
  double wall = 0;
  double cpu = 0;  // this thread's CPU time: steadier than wall time when other jobs share the machine
};

template <typename F>
Medians medianSeconds(int runs, F&& f) {
  std::vector<double> wall, cpu;
  for (int r = 0; r < runs; ++r) {
    const double c0 = threadCpuSeconds();
    auto t0 = std::chrono::steady_clock::now();
    f();
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(threadCpuSeconds() - c0);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> counts;
  int size = 256, runs = 5;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--spheres" && i + 1 < argc) counts.push_back(std::atoi(argv[++i]));
    else if (a == "--size" && i + 1 < argc) size = std::atoi(argv[++i]);
    else if (a == "--runs" && i + 1 < argc) runs = std::atoi(argv[++i]);
    else {
      fmt::print(stderr, "usage: embree_peer_bench [--spheres N]... [--size W] [--runs R]\n");
      return 2;
    }
  }
  if (counts.empty()) counts = {10, 100, 1000, 10000};
  if (size < 8 || runs < 1) {
    fmt::print(stderr, "embree_peer_bench: --size must be >= 8 and --runs >= 1\n");
    return 2;
  }

  RTCDevice device = rtcNewDevice("threads=1");
  if (!device) {
    fmt::print(stderr, "embree_peer_bench: rtcNewDevice failed\n");
    return 1;
  }
  fmt::print("# {}x{} primary rays, single thread, median of {} runs\n", size, size, runs);
  fmt::print("# ratio = lattice / embree; cpu: the same runs' thread CPU time (steadier on a loaded machine)\n");
  fmt::print("{:>7} {:>11} {:>11} {:>7} {:>11} {:>11} {:>7} {:>9} {:>10}\n", "spheres", "lattice_ms", "embree_ms",
             "ratio", "lat_cpu_ms", "emb_cpu_ms", "ratio", "agree_%", "max_dt");
  for (int n : counts) {
    SphereSet set = randomSpheres(n, 1988u + static_cast<unsigned>(n));

    std::vector<PrimitivePtr<double>> leaves;
    QuarticShape s = sphere(set.radius);
    for (const Vec3d& c : set.centres) {
      Mat4d m(1.0);
      m[3] = glm::dvec4(c, 1.0);
      leaves.push_back(makeQuarticLeaf<double>(s.f, s.bounds, m, 0));
    }
    PrimitivePtr<double> uni = makeCsgNode<double>(CsgOp::Union, std::move(leaves));

    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* verts = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), static_cast<size_t>(n)));
    for (int i = 0; i < n; ++i) {
      verts[4 * i + 0] = static_cast<float>(set.centres[i].x);
      verts[4 * i + 1] = static_cast<float>(set.centres[i].y);
      verts[4 * i + 2] = static_cast<float>(set.centres[i].z);
      verts[4 * i + 3] = static_cast<float>(set.radius);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);

    std::vector<double> ours(static_cast<size_t>(size * size)), theirs(static_cast<size_t>(size * size));
    const Medians lat = medianSeconds(runs, [&] {
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          Hit<double> hit;
          Ray<double> r = primaryRay(x, y, size);
          ours[static_cast<size_t>(y * size + x)] = uni->firstHit(r, 0.0, 1e30, hit) ? hit.t : -1.0;
        }
    });
    const Medians emb = medianSeconds(runs, [&] {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          Ray<double> r = primaryRay(x, y, size);
          RTCRayHit rh;
          std::memset(&rh, 0, sizeof rh);
          rh.ray.org_x = static_cast<float>(r.origin.x);
          rh.ray.org_y = static_cast<float>(r.origin.y);
          rh.ray.org_z = static_cast<float>(r.origin.z);
          rh.ray.dir_x = static_cast<float>(r.direction.x);
          rh.ray.dir_y = static_cast<float>(r.direction.y);
          rh.ray.dir_z = static_cast<float>(r.direction.z);
          rh.ray.tnear = 0.0f;
          rh.ray.tfar = 1e30f;
          rh.ray.mask = 0xFFFFFFFFu;
          rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          rtcIntersect1(scene, &context, &rh);
          theirs[static_cast<size_t>(y * size + x)] =
              rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1.0 : static_cast<double>(rh.ray.tfar);
        }
    });
    // Agreement: same hit/miss, and t equal to float precision (Embree is single precision).
    long agree = 0;
    double maxDt = 0;
    for (size_t i = 0; i < ours.size(); ++i) {
      bool hitA = ours[i] >= 0, hitB = theirs[i] >= 0;
      if (hitA != hitB) continue;
      if (hitA) {
        double dt = std::abs(ours[i] - theirs[i]) / std::max(1.0, std::abs(ours[i]));
        maxDt = std::max(maxDt, dt);
        if (dt > 1e-4) continue;
      }
      ++agree;
    }
    fmt::print("{:>7} {:>11.2f} {:>11.2f} {:>7.2f} {:>11.2f} {:>11.2f} {:>7.2f} {:>9.3f} {:>10.2e}\n", n,
               lat.wall * 1e3, emb.wall * 1e3, lat.wall / emb.wall, lat.cpu * 1e3, emb.cpu * 1e3, lat.cpu / emb.cpu,
               100.0 * static_cast<double>(agree) / static_cast<double>(ours.size()), maxDt);
    rtcReleaseScene(scene);
  }
  rtcReleaseDevice(device);
  return 0;
}
