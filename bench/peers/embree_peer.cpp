// The Embree 3 peer (Debian's libembree-dev) for bench/peers.sh: loads a
// scene through our own loader, traces it with Embree and eq. 2.3, writes a
// PNG and prints its own pure trace time.
//
//   embree_peer SCENE.toml -o OUT.png [--threads N] [--width W --height H]
//
// Method and tunables:
//  * geometry (bench/peers/peer_scene.hpp): spheres as Embree's sphere
//    points, tubes (polylines, capsules) as round linear curves with their
//    segments' neighbour flags set so joints are spheres, not caps; each
//    lattice's exact object is one Embree scene placed by one instance per
//    lattice instance; planes (half-spaces) are closed forms beside Embree,
//    tested on every primary and shadow ray. Embree works in float.
//  * rays: our Camera<double>'s primary rays; shadow rays by rtcOccluded1
//    from the hit lifted kShadowOffset x max(1, |p|) along the facing normal
//    (float hits are rougher than our double ones; 1e-4 keeps hair from
//    shadowing itself and is under 2 % of the hair radius of the examples).
//  * shading: render/scene/shading.hpp's shade(), our eq. 2.3 itself, in double;
//    pixels round(255 v) as our renderer writes them.
//  * threads: rows interleaved over N std::threads; the trace time is the
//    wall time of that loop (no load, no BVH build, no PNG).
#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "bench/peers/peer_scene.hpp"
#include "foundation/error.hpp"
#include "io/png.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "render/scene/camera.hpp"
#include "render/renderer.hpp"
#include "render/scene/shading.hpp"

using namespace lattice;
using namespace lattice::peers;

namespace {

constexpr double kShadowOffset = 1e-4;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// What a hit on a geometry of the top scene, or of a shared object, means.
struct GeometryInfo {
  std::vector<std::optional<MaterialId>> materials;  // per primitive
};

struct InstanceInfo {
  std::size_t object = 0;
  Mat4d toWorld{1.0};
  glm::dmat3 normalToWorld{1.0};
  MaterialId material = 0;
};

class EmbreeScene {
 public:
  EmbreeScene(const PeerScene& scene, unsigned threads) : planes_(scene.planes) {
    device_ = rtcNewDevice(fmt::format("threads={}", threads).c_str());
    if (!device_) throw Error(ErrorKind::Internal, "rtcNewDevice failed");
    top_ = rtcNewScene(device_);
    topGeometry_ = addObject(top_, scene.world);
    for (const PeerObject& object : scene.shared) {
      RTCScene s = rtcNewScene(device_);
      sharedGeometry_.push_back(addObject(s, object));
      rtcCommitScene(s);
      shared_.push_back(s);
    }
    for (const PeerInstance& inst : scene.instances) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(g, shared_[inst.object]);
      float m[16];
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c * 4 + r] = static_cast<float>(inst.toWorld[c][r]);
      rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, m);
      rtcCommitGeometry(g);
      const unsigned id = rtcAttachGeometry(top_, g);
      rtcReleaseGeometry(g);
      if (instances_.size() <= id) instances_.resize(id + 1);
      instances_[id] = {inst.object, inst.toWorld, glm::transpose(glm::inverse(glm::dmat3(inst.toWorld))),
                        inst.material};
    }
    rtcCommitScene(top_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw Error(ErrorKind::Internal, "Embree reported an error");
  }
  ~EmbreeScene() {
    for (RTCScene s : shared_) rtcReleaseScene(s);
    rtcReleaseScene(top_);
    rtcReleaseDevice(device_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  struct Hit {
    double t = 0;
    Vec3d normal{0.0};  // world, unit
    MaterialId material = 0;
  };

  bool firstHit(const Vec3d& origin, const Vec3d& direction, Hit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    setRay(rh.ray, origin, direction, kInfinity);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_, &context, &rh);
    bool found = false;
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
      found = true;
      hit.t = rh.ray.tfar;
      Vec3d n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
      if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        const InstanceInfo& inst = instances_[rh.hit.instID[0]];
        n = inst.normalToWorld * n;
        hit.material = sharedGeometry_[inst.object][rh.hit.geomID].materials[rh.hit.primID].value_or(inst.material);
      } else {
        hit.material = topGeometry_[rh.hit.geomID].materials[rh.hit.primID].value_or(0);
      }
      hit.normal = glm::normalize(n);
    }
    for (const PeerPlane& p : planes_) {
      const double t = planeHit(p, origin, direction);
      if (t > 0 && (!found || t < hit.t)) {
        found = true;
        hit = {t, p.normal, p.material};
      }
    }
    return found;
  }

  bool occluded(const Vec3d& origin, const Vec3d& toLight) const {
    for (const PeerPlane& p : planes_) {
      const double t = planeHit(p, origin, toLight);
      if (t > 0 && t < 1) return true;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    setRay(ray, origin, toLight, 1.0f);
    rtcOccluded1(top_, &context, &ray);
    return ray.tfar < 0;
  }

 private:
  // Spheres and tubes of one object as (up to) two geometries; returns what
  // each attached geometry id means.
  std::vector<GeometryInfo> addObject(RTCScene scene, const PeerObject& object) {
    std::vector<GeometryInfo> info;
    auto remember = [&](RTCGeometry g, GeometryInfo what) {
      rtcCommitGeometry(g);
      const unsigned id = rtcAttachGeometry(scene, g);
      rtcReleaseGeometry(g);
      if (info.size() <= id) info.resize(id + 1);
      info[id] = std::move(what);
    };
    if (!object.spheres.empty()) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                            4 * sizeof(float), object.spheres.size()));
      GeometryInfo what;
      for (const PeerSphere& s : object.spheres) {
        *v++ = float(s.centre.x), *v++ = float(s.centre.y), *v++ = float(s.centre.z), *v++ = float(s.radius);
        what.materials.push_back(s.material);
      }
      remember(g, std::move(what));
    }
    std::size_t vertices = 0, segments = 0;
    for (const PeerTube& t : object.tubes) vertices += t.points.size(), segments += t.points.size() - 1;
    if (segments > 0) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
      auto* v = static_cast<float*>(
          rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), vertices));
      auto* index = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), segments));
      auto* flags = static_cast<unsigned char*>(
          rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_FLAGS, 0, RTC_FORMAT_UCHAR, 1, segments));
      GeometryInfo what;
      unsigned base = 0;
      for (const PeerTube& t : object.tubes) {
        for (const Vec3d& p : t.points)
          *v++ = float(p.x), *v++ = float(p.y), *v++ = float(p.z), *v++ = float(t.radius);
        const std::size_t n = t.points.size() - 1;
        for (std::size_t s = 0; s < n; ++s) {
          *index++ = base + unsigned(s);
          *flags++ = static_cast<unsigned char>((s > 0 ? RTC_CURVE_FLAG_NEIGHBOR_LEFT : 0) |
                                                (s + 1 < n ? RTC_CURVE_FLAG_NEIGHBOR_RIGHT : 0));
          what.materials.push_back(t.material);
        }
        base += unsigned(t.points.size());
      }
      remember(g, std::move(what));
    }
    return info;
  }

  static void setRay(RTCRay& ray, const Vec3d& origin, const Vec3d& direction, float tfar) {
    ray.org_x = float(origin.x), ray.org_y = float(origin.y), ray.org_z = float(origin.z);
    ray.dir_x = float(direction.x), ray.dir_y = float(direction.y), ray.dir_z = float(direction.z);
    ray.tnear = 0.0f;
    ray.tfar = tfar;
    ray.mask = ~0u;
    ray.time = 0.0f;
    ray.flags = 0;
  }

  static double planeHit(const PeerPlane& p, const Vec3d& origin, const Vec3d& direction) {
    const double denominator = glm::dot(p.normal, direction);
    if (denominator == 0) return -1;
    return (p.offset - glm::dot(p.normal, origin)) / denominator;
  }

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  std::vector<RTCScene> shared_;
  std::vector<GeometryInfo> topGeometry_;
  std::vector<std::vector<GeometryInfo>> sharedGeometry_;
  std::vector<InstanceInfo> instances_;
  std::vector<PeerPlane> planes_;
};

struct Args {
  std::string scene, output;
  unsigned threads = 1;
  int width = 0, height = 0;
};

Args parseArgs(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(ErrorKind::Usage, fmt::format("{} needs a value (see --help)", arg));
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      fmt::print("embree_peer SCENE.toml -o OUT.png [--threads N] [--width W --height H]\n"
                 "Traces SCENE with Embree 3 (round linear curves for hair, instanced; sphere points; planes in\n"
                 "closed form; rtcOccluded1 shadow rays; eq. 2.3) and prints `trace_seconds S`: the trace alone.\n"
                 "Scenes with intersections, differences, tori or general quartics are refused (exit 3).\n");
      std::exit(0);
    } else if (arg == "-o" || arg == "--output") {
      a.output = value();
    } else if (arg == "--threads") {
      a.threads = static_cast<unsigned>(std::stoul(value()));
    } else if (arg == "--width") {
      a.width = std::stoi(value());
    } else if (arg == "--height") {
      a.height = std::stoi(value());
    } else if (a.scene.empty() && arg[0] != '-') {
      a.scene = arg;
    } else {
      throw Error(ErrorKind::Usage, fmt::format("unknown argument '{}' (see --help)", arg));
    }
  }
  if (a.scene.empty() || a.output.empty()) throw Error(ErrorKind::Usage, "give SCENE.toml and -o OUT.png (see --help)");
  if (a.threads < 1) a.threads = 1;
  return a;
}

LightingModel<double> lightingOf(const SceneDesc& scene) {
  LightingModel<double> model;
  model.ambient = scene.options.ambient;
  model.attenuationK = scene.options.attenuationK;
  model.lights = scene.lights;
  for (const NamedMaterial& m : scene.materials) model.materials.push_back(m.material);
  return model;
}

int run(const Args& args) {
  const auto t0 = std::chrono::steady_clock::now();
  const SceneDesc scene = lht::loadSceneWithLattices(args.scene).scene;
  const int width = args.width > 0 ? args.width : scene.options.width;
  const int height = args.height > 0 ? args.height : scene.options.height;
  const EmbreeScene embree(flattenScene(scene), args.threads);
  const double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const Camera<double> camera(scene.camera, width, height);
  const LightingModel<double> model = lightingOf(scene);
  const Vec3d background = glm::clamp(scene.options.background, Vec3d(0.0), Vec3d(1.0));
  const double scale = std::min(1.0, viewingDistance(scene.camera));
  RgbImage image(width, height);
  auto traceRows = [&](unsigned first) {
    for (int y = static_cast<int>(first); y < height; y += static_cast<int>(args.threads))
      for (int x = 0; x < width; ++x) {
        const Ray<double> ray = camera.primaryRay(x, y);
        EmbreeScene::Hit hit;
        Vec3d colour = background;
        if (embree.firstHit(ray.origin, ray.direction, hit)) {
          const Vec3d point = ray.origin + ray.direction * hit.t;
          colour = shade(model, point, hit.normal, -ray.direction, hit.material, [&](std::size_t i, const Vec3d& n) {
            if (!scene.options.shadows) return true;
            const double lift = kShadowOffset * std::max({scale, std::abs(point.x), std::abs(point.y), std::abs(point.z)});
            const Vec3d origin = point + n * lift;
            return !embree.occluded(origin, model.lights[i].position - origin);
          });
        }
        std::uint8_t* p = image.pixel(x, y);
        for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(quantize8(colour[c]));
      }
  };
  const auto t1 = std::chrono::steady_clock::now();
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < args.threads; ++t) workers.emplace_back(traceRows, t);
  traceRows(0);
  for (std::thread& w : workers) w.join();
  const double traceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  io::writePng(args.output, image);
  fmt::print("embree_peer: {} {}x{}, {} threads: load + build {:.4f} s, picture {}\ntrace_seconds {:.4f}\n",
             args.scene, width, height, args.threads, buildSeconds, args.output, traceSeconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parseArgs(argc, argv));
  } catch (const Error& e) {
    fmt::print(stderr, "embree_peer: {}\n", e.what());
    return static_cast<int>(e.kind());
  } catch (const std::exception& e) {
    fmt::print(stderr, "embree_peer: {}\n", e.what());
    return 1;
  }
}
