#include "render/renderer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "foundation/error.hpp"
#include "foundation/progress.hpp"
#include "foundation/arithmetics.hpp"
#include "foundation/threads.hpp"

namespace lattice {

namespace {

constexpr int kMaxImageSide = 16384;
constexpr int kMaxThreads = 256;

int resolveThreads(int requested) {
  if (requested < 0 || requested > kMaxThreads)
    throw Error(ErrorKind::Usage, fmt::format("--threads {} is out of range; use 1..{} (or 0 for all cores)",
                                              requested, kMaxThreads));
  if (requested > 0) return requested;
  return static_cast<int>(std::min<unsigned>(hardwareThreads(), kMaxThreads));
}

int resolveSide(int requested, int sceneDefault, const char* name) {
  const int v = requested > 0 ? requested : sceneDefault;
  if (requested < 0 || v < 1 || v > kMaxImageSide)
    throw Error(ErrorKind::Usage, fmt::format("image {} {} is out of range; use 1..{}", name, requested < 0 ? requested : v,
                                              kMaxImageSide));
  return v;
}

// Runs work(y) for y in [y0, y1) on `threads` threads. Rows are handed out
// one at a time from a shared counter, so uneven rows balance out; which
// thread renders a row never changes its pixels.
template <typename Work>
void parallelRows(int y0, int y1, int threads, Work&& work) {
  const int n = std::min(threads, y1 - y0);
  if (n <= 1) {
    for (int y = y0; y < y1; ++y) work(y);
    return;
  }
  std::atomic<int> next{y0};
  runWorkers(
      static_cast<unsigned>(n),
      [&](unsigned) {
        for (int y = next.fetch_add(1); y < y1; y = next.fetch_add(1)) work(y);
      },
      [&] { next.store(y1); });
}

}  // namespace

template <typename T>
Renderer<T>::Renderer(const SceneDesc& scene, const RenderSettings& settings, NodeDesc* release)
    : width_(resolveSide(settings.width, scene.options.width, "width")),
      height_(resolveSide(settings.height, scene.options.height, "height")),
      threads_(resolveThreads(settings.threads)),
      camera_(scene.camera, width_, height_),
      root_(release ? buildPrimitive<T>(std::move(*release), Mat4d(1.0), settings.build, 0)
                    : buildPrimitive<T>(scene.root, Mat4d(1.0), settings.build, 0)),
      background_(Vec3<T>(glm::clamp(scene.options.background, Vec3d(0.0), Vec3d(1.0)))),
      shadows_(scene.options.shadows),
      offsetScale_(static_cast<T>(std::min(1.0, viewingDistance(scene.camera)))),
      bands_(width_, height_, threads_, [this](int y, Color18* out) { shadeRow(y, out); }) {
  lighting_.ambient = Vec3<T>(scene.options.ambient);
  lighting_.attenuationK = static_cast<T>(scene.options.attenuationK);
  for (const auto& light : scene.lights) lighting_.lights.push_back(light.template cast<T>());
  for (const auto& m : scene.materials) lighting_.materials.push_back(m.material.template cast<T>());
}

template <typename T>
Renderer<T>::~Renderer() = default;

template <typename T>
Vec3<T> Renderer<T>::trace(const Ray<T>& ray, std::uint64_t& rays, OccluderCache<T>& occluders) const {
  ++rays;
  Hit<T> hit;
  if (!root_->firstHit(ray, T(0), std::numeric_limits<T>::infinity(), hit)) return background_;
  const Vec3<T> point = ray.at(hit.t);
  const Vec3<T> toObserver = -ray.direction;
  return shade(lighting_, point, hit.normal, toObserver, hit.material, [&](std::size_t i, const Vec3<T>& facing) {
    if (!shadows_) return true;
    ++rays;
    return !occluders.blocked(*root_, shadowRay(point, facing, lighting_.lights[i].position, offsetScale_), i);
  });
}

template <typename T>
Vec3<T> Renderer<T>::trace(const Ray<T>& ray) const {
  std::uint64_t rays = 0;
  OccluderCache<T> occluders(lighting_.lights.size());
  Vec3<T> c = trace(ray, rays, occluders);
  rays_.add(rays);
  return c;
}

template <typename T>
Vec3<T> Renderer<T>::pixel(int x, int y) const {
  return trace(camera_.primaryRay(x, y));
}

template <typename T>
void Renderer<T>::rowLinear(int y, std::span<Vec3<T>> out) const {
  if (y < 0 || y >= height_ || out.size() != static_cast<std::size_t>(width_))
    throw Error(ErrorKind::Internal, fmt::format("row {} of {} asked with a buffer of {} for width {}", y, height_,
                                                 out.size(), width_));
  std::uint64_t rays = 0;
  OccluderCache<T> occluders(lighting_.lights.size());  // the row's own: shared by no other thread
  for (int x = 0; x < width_; ++x)
    out[static_cast<std::size_t>(x)] = trace(camera_.primaryRay(x, y), rays, occluders);
  rays_.add(rays);
}

template <typename T>
void Renderer<T>::shadeRow(int y, Color18* out) const {
  std::vector<Vec3<T>> linear(static_cast<std::size_t>(width_));
  rowLinear(y, linear);
  for (int x = 0; x < width_; ++x) {
    const Vec3<T>& c = linear[static_cast<std::size_t>(x)];
    out[x] = packColor18(quantizeLevel<kLevels6>(c.r), quantizeLevel<kLevels6>(c.g), quantizeLevel<kLevels6>(c.b));
  }
}

template <typename T>
void Renderer<T>::row(int y, std::span<Color18> out) {
  if (y < 0 || y >= height_ || out.size() != static_cast<std::size_t>(width_))
    throw Error(ErrorKind::Internal, fmt::format("row {} of {} asked with a buffer of {} for width {}", y, height_,
                                                 out.size(), width_));
  bands_.row(y, out);
}

template <typename T>
RgbImage renderImage(Renderer<T>& renderer, Progress* progress) {
  RgbImage image(renderer.width(), renderer.height());
  parallelRows(0, renderer.height(), renderer.threads(), [&](int y) {
    std::vector<Vec3<T>> linear(static_cast<std::size_t>(renderer.width()));
    renderer.rowLinear(y, linear);
    for (int x = 0; x < renderer.width(); ++x) {
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<std::uint8_t>(quantizeLevel<kLevels8>(linear[static_cast<std::size_t>(x)][c]));
    }
    if (progress) progress->advance();
  });
  return image;
}

#define LATTICE_INSTANTIATE(T) \
  template class Renderer<T>; \
  template RgbImage renderImage<T>(Renderer<T>&, Progress*);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
