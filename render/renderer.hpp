#pragma once
// The row renderer ("model" in the thesis): primary ray per pixel, first hit
// in the CSG tree, eq. 2.3 with shadow rays (render/scene/shading.hpp).
//
// Output per pixel is linear RGB clamped to [0, 1] in T, and the 18-bit
// colour the thesis's model produced: each channel v becomes round(v * 63)
// (6 bits, 0..63, nearest level; 0.5/63 rounds up), packed as Color18.
// No gamma curve is applied anywhere: values are the light intensities of
// eq. 2.3 as they are.
//
// Every pixel depends only on its own rays, so rows may be rendered in any
// order, on any number of threads, with identical results (RowSource18's
// determinism).
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "foundation/counter.hpp"
#include "foundation/rgb_image.hpp"
#include "foundation/scanline.hpp"
#include "render/band_cache.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/occluder_cache.hpp"
#include "render/scene/scene.hpp"
#include "render/scene/shading.hpp"
#include "foundation/arithmetics.hpp"
#include "foundation/threads.hpp"

namespace lattice {

class Progress;

struct RenderSettings {
  int width = 0;    // 0: the scene's [options] width
  int height = 0;   // 0: the scene's [options] height
  int threads = 0;  // 0: hardwareThreads() (foundation/threads.hpp)
  BuildOptions build;
};

// The two channel depths the renderer writes: the thesis's 6-bit colour
// (Color18) and 8-bit images.
inline constexpr unsigned kLevels6 = 63;
inline constexpr unsigned kLevels8 = 255;

// A linear intensity clamped to [0, 1] as the nearest of Levels + 1 levels
// (0..Levels; a half rounds up). The IEEE types round in double (one
// multiply, add 0.5, truncate); fixed point in its own integers (no double
// per pixel), which the level count must not overflow.
template <unsigned Levels, typename T>
unsigned quantizeLevel(T v) {
  static_assert(Levels >= 1, "a channel has at least two levels");
  if constexpr (kIsIeee<T>) {
    const double d = static_cast<double>(v);
    const double c = d < 0 ? 0 : (d > 1 ? 1 : d);
    return static_cast<unsigned>(c * double(Levels) + 0.5);
  } else {
    using Raw = typename T::Raw;
    static_assert(Levels <= (Raw(1) << (sizeof(Raw) * 8 - 2 - T::kFractionBits)),
                  "this many levels overflow the fixed-point product");
    const T c = v < T(0) ? T(0) : (v > T(1) ? T(1) : v);
    const auto one = Raw(1) << T::kFractionBits;
    return static_cast<unsigned>((c.raw() * static_cast<Raw>(Levels) + one / 2) >> T::kFractionBits);
  }
}
// 6- and 8-bit channels of a double intensity.
inline unsigned quantize6(double v) { return quantizeLevel<kLevels6>(v); }
inline unsigned quantize8(double v) { return quantizeLevel<kLevels8>(v); }

template <typename T>
class Renderer final : public RowSource18 {
 public:
  // Builds the primitive tree for T once. Throws lattice::Error on a scene
  // that cannot be built or a bad size/thread count (Usage).
  Renderer(const SceneDesc& scene, const RenderSettings& settings = {}) : Renderer(scene, settings, nullptr) {}
  // The same, releasing the scene's node tree while building it
  // (buildPrimitive of a NodeDesc&&): scene.root is left with no operands,
  // the rest of the scene as it was.
  Renderer(SceneDesc&& scene, const RenderSettings& settings = {}) : Renderer(scene, settings, &scene.root) {}
  ~Renderer() override;

  int width() const override { return width_; }
  int height() const override { return height_; }
  int threads() const { return threads_; }

  // Row y as 18-bit colour, through the band cache (render/band_cache.hpp):
  // a band of rows rendered at once and kept, the next one rendered ahead
  // on the renderer's threads while the consumer reads this one.
  void row(int y, std::span<Color18> out) override;

  // Row y in full precision (linear, clamped to [0, 1]); single-threaded and
  // safe to call from several threads at once.
  void rowLinear(int y, std::span<Vec3<T>> out) const;
  // One pixel (x, y), row 0 at the top.
  Vec3<T> pixel(int x, int y) const;
  // The colour seen along any ray (background if it hits nothing).
  Vec3<T> trace(const Ray<T>& ray) const;

  // Primary plus shadow rays traced so far (statistics).
  std::uint64_t raysTraced() const { return rays_.value(); }
  const Primitive<T>& root() const { return *root_; }
  const Camera<T>& camera() const { return camera_; }

 private:
  // release: scene.root, built by buildPrimitive of a NodeDesc&&; null: kept.
  Renderer(const SceneDesc& scene, const RenderSettings& settings, NodeDesc* release);

  // Counts the rays in `rays`; shadow rays ask `occluders` first.
  Vec3<T> trace(const Ray<T>& ray, std::uint64_t& rays, OccluderCache<T>& occluders) const;
  void shadeRow(int y, Color18* out) const;

  int width_ = 0, height_ = 0, threads_ = 1;
  Camera<T> camera_;
  PrimitivePtr<T> root_;
  LightingModel<T> lighting_;
  Vec3<T> background_{};
  bool shadows_ = true;
  // The smallest length shadow-ray offsets are measured against
  // (surfaceOffset): min(1, the camera's viewing distance).
  T offsetScale_{1};
  mutable Counter rays_;

  // Last, so its threads are stopped before what they read goes.
  BandCache bands_;
};

#define LATTICE_DECLARE(T) extern template class Renderer<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

// Renders every row into an 8-bit image (each channel round(v * 255) of the
// full-precision value, not of the 18-bit one) on the renderer's threads,
// advancing `progress` (may be null) by one per row.
template <typename T>
RgbImage renderImage(Renderer<T>& renderer, Progress* progress = nullptr);

#define LATTICE_DECLARE(T) extern template RgbImage renderImage<T>(Renderer<T>&, Progress*);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
