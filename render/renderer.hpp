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

#include "foundation/rgb_image.hpp"
#include "foundation/scanline.hpp"
#include "render/scene/camera.hpp"
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

// 6-bit channel of a linear intensity in [0, 1], rounded to nearest.
inline unsigned quantize6(double v) {
  const double c = v < 0 ? 0 : (v > 1 ? 1 : v);
  return static_cast<unsigned>(c * 63.0 + 0.5);
}
inline unsigned quantize8(double v) {
  const double c = v < 0 ? 0 : (v > 1 ? 1 : v);
  return static_cast<unsigned>(c * 255.0 + 0.5);
}
// The same for the renderer's scalar: fixed point rounds in integers (no
// double per pixel), the IEEE types go through the double versions above.
template <typename T>
unsigned quantizeLevel(T v, unsigned levels) {
  if constexpr (kIsIeee<T>) {
    return levels == 63 ? quantize6(static_cast<double>(v)) : quantize8(static_cast<double>(v));
  } else {
    const T c = v < T(0) ? T(0) : (v > T(1) ? T(1) : v);
    const auto one = typename T::Raw(1) << T::kFractionBits;
    return static_cast<unsigned>((c.raw() * static_cast<typename T::Raw>(levels) + one / 2) >> T::kFractionBits);
  }
}

template <typename T>
class Renderer final : public RowSource18 {
 public:
  // Builds the primitive tree for T once. Throws lattice::Error on a scene
  // that cannot be built or a bad size/thread count (Usage).
  Renderer(const SceneDesc& scene, const RenderSettings& settings = {});
  ~Renderer() override;

  int width() const override { return width_; }
  int height() const override { return height_; }
  int threads() const { return threads_; }

  // Row y as 18-bit colour. Renders a band of rows at once and keeps it; with
  // several threads a pool started once renders the following band while
  // the consumer reads this one, so a consumer asking row by row keeps every
  // core busy without starting threads per band.
  void row(int y, std::span<Color18> out) override;

  // Row y in full precision (linear, clamped to [0, 1]); single-threaded and
  // safe to call from several threads at once.
  void rowLinear(int y, std::span<Vec3<T>> out) const;
  // One pixel (x, y), row 0 at the top.
  Vec3<T> pixel(int x, int y) const;
  // The colour seen along any ray (background if it hits nothing).
  Vec3<T> trace(const Ray<T>& ray) const;

  // Primary plus shadow rays traced so far (statistics).
  std::uint64_t raysTraced() const { return rays_.load(std::memory_order_relaxed); }
  const Primitive<T>& root() const { return *root_; }
  const Camera<T>& camera() const { return camera_; }

 private:
  Vec3<T> trace(const Ray<T>& ray, std::uint64_t& rays) const;
  int bandRowsAt(int y0) const;
  void shadeRow(int y, Color18* out) const;
  void renderBandHere(int y0);
  void startBandAhead(int y0);
  void takeBandAhead();

  int width_ = 0, height_ = 0, threads_ = 1;
  Camera<T> camera_;
  PrimitivePtr<T> root_;
  LightingModel<T> lighting_;
  Vec3<T> background_{};
  bool shadows_ = true;
  // The smallest length shadow-ray offsets are measured against
  // (surfaceOffset): min(1, the camera's viewing distance).
  T offsetScale_{1};
  mutable std::atomic<std::uint64_t> rays_{0};

  // The band cache of row(): rows [bandStart_, bandStart_ + bandRows_). With
  // more than one thread the pool renders the next band into ahead_ while the
  // consumer reads this one (aheadStart_ >= 0 while it is under way).
  Mutex bandMutex_;
  int bandStart_ = -1;
  int bandRows_ = 0;
  std::vector<Color18> band_;
  int aheadStart_ = -1;
  int aheadRows_ = 0;
  std::vector<Color18> ahead_;
  std::atomic<int> aheadNext_{0};
  // Last, so it is stopped (waiting for its band) before what it writes goes.
  std::unique_ptr<WorkerPool> pool_;
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
