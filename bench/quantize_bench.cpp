// Quality, time and memory of the quantizer options, side by side with
// Debian's pngquant. Figures in docs/quantize.md come from this program:
//
//   quantize_bench [--quick] [--keep DIR] [extra.png ...]
//
// Inputs: two procedurally generated "ordinary photograph"-like images (see
// makeLandscape / makeStillLife) plus any PNG named on the command line.
// Quality: MSE per channel and PSNR against the original 8-bit truecolour
// image (so our figures include the 6-bit-per-channel rounding of the 18-bit
// path; that floor is printed as "18-bit floor"). Time: best of 3 wall-clock
// runs of runPipeline. Memory: peak bytes allocated through operator new
// during the run (the sink computes the error row by row and keeps nothing),
// i.e. the pipeline's own working set. pngquant is run as a child process; its
// time includes process start and PNG encode/decode and its memory is the
// child's peak RSS (wait4), so those two columns are not like for like.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "io/png.hpp"
#include "foundation/rgb_image_source.hpp"
#include "quantize/run_pipeline.hpp"

extern char** environ;

// ---- allocation accounting (peak live bytes) ----
namespace {
std::atomic<long long> liveBytes{0};
std::atomic<long long> peakBytes{0};
void noteAlloc(std::size_t n) {
  long long now = liveBytes += static_cast<long long>(n);
  long long peak = peakBytes.load();
  while (now > peak && !peakBytes.compare_exchange_weak(peak, now)) {
  }
}
}  // namespace

void* operator new(std::size_t n) {
  void* p = std::malloc(n + 16);
  if (!p) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  noteAlloc(n);
  return static_cast<char*>(p) + 16;
}
void operator delete(void* p) noexcept {
  if (!p) return;
  char* base = static_cast<char*>(p) - 16;
  liveBytes -= static_cast<long long>(*reinterpret_cast<std::size_t*>(base));
  std::free(base);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace {

using lattice::RgbImage;

// ---- procedural test images ----
std::uint32_t hash2(int x, int y, std::uint32_t seed) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 0x27d4eb2du ^ static_cast<std::uint32_t>(y) * 0x165667b1u ^ seed;
  h ^= h >> 15;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}
double unitNoise(int x, int y, std::uint32_t seed) { return double(hash2(x, y, seed) & 0xFFFF) / 65535.0; }
// Smooth value noise: bilinear interpolation of a lattice of random values.
double valueNoise(double x, double y, std::uint32_t seed) {
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  double fx = x - x0, fy = y - y0;
  fx = fx * fx * (3 - 2 * fx);
  fy = fy * fy * (3 - 2 * fy);
  double a = unitNoise(x0, y0, seed), b = unitNoise(x0 + 1, y0, seed);
  double c = unitNoise(x0, y0 + 1, seed), d = unitNoise(x0 + 1, y0 + 1, seed);
  return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}
double fractal(double x, double y, std::uint32_t seed) {
  double sum = 0, amp = 0.5, freq = 1;
  for (int octave = 0; octave < 4; ++octave, amp *= 0.5, freq *= 2) sum += amp * valueNoise(x * freq, y * freq, seed + octave);
  return sum;
}
std::uint8_t to8(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }
void put(RgbImage& im, int x, int y, double r, double g, double b) {
  std::uint8_t* p = im.pixel(x, y);
  p[0] = to8(r);
  p[1] = to8(g);
  p[2] = to8(b);
}

// A landscape: sky gradient with a sun and its glow, hills of textured
// green/brown, a lake reflecting the sky, and sensor noise.
RgbImage makeLandscape(int w, int h) {
  RgbImage im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double u = double(x) / w, v = double(y) / h;
      double horizon = 0.55 + 0.08 * std::sin(u * 7.0) + 0.05 * fractal(u * 6, 0.5, 11);
      double r, g, b;
      if (v < horizon) {
        double t = v / horizon;
        r = 60 + 170 * t;
        g = 110 + 100 * t;
        b = 220 - 40 * t;
        double dx = u - 0.72, dy = v - 0.22, d = std::sqrt(dx * dx + dy * dy);
        double glow = std::exp(-d * 9.0);
        r += 120 * glow;
        g += 90 * glow;
        b += 20 * glow;
        if (d < 0.045) r = 255, g = 244, b = 210;
        double cloud = std::max(0.0, fractal(u * 5, v * 9, 3) - 0.55) * 2.2;
        r += (250 - r) * cloud;
        g += (250 - g) * cloud;
        b += (252 - b) * cloud;
      } else if (v < 0.8 || u < 0.3) {
        double tex = fractal(u * 40, v * 40, 7);
        double shade = 0.6 + 0.5 * (v - horizon);
        r = (70 + 90 * tex) * shade;
        g = (100 + 80 * tex) * shade + 20;
        b = (35 + 30 * tex) * shade;
      } else {
        double ripple = 0.5 + 0.5 * std::sin(v * 180 + 6 * fractal(u * 8, v * 30, 5));
        r = 50 + 40 * ripple;
        g = 90 + 50 * ripple;
        b = 150 + 60 * ripple;
      }
      double noise = (unitNoise(x, y, 99) - 0.5) * 10;
      put(im, x, y, r + noise, g + noise, b + noise);
    }
  return im;
}

// A still life: a warm wall with a vignette, a table, three shaded balls of
// saturated colour with highlights, a striped cloth, and sensor noise.
RgbImage makeStillLife(int w, int h) {
  RgbImage im(w, h);
  struct Ball {
    double cx, cy, radius, r, g, b;
  };
  const Ball balls[] = {{0.3, 0.55, 0.14, 200, 30, 40}, {0.55, 0.6, 0.11, 40, 150, 60}, {0.75, 0.5, 0.12, 50, 70, 200}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double u = double(x) / w, v = double(y) / h;
      double vignette = 1.0 - 0.6 * ((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5));
      double r, g, b;
      if (v < 0.62) {
        double plaster = fractal(u * 30, v * 30, 21);
        r = (190 + 40 * plaster) * vignette;
        g = (150 + 35 * plaster) * vignette;
        b = (110 + 25 * plaster) * vignette;
      } else {
        bool stripe = int((u + 0.3 * v) * 24) % 2 == 0 && u > 0.45;
        double grain = fractal(u * 4, v * 60, 31);
        r = stripe ? 230 : 120 + 60 * grain;
        g = stripe ? 225 : 70 + 35 * grain;
        b = stripe ? 215 : 35 + 20 * grain;
        r *= vignette;
        g *= vignette;
        b *= vignette;
      }
      for (const Ball& ball : balls) {
        double dx = (u - ball.cx) * w / h, dy = v - ball.cy;
        double d2 = (dx * dx + dy * dy) / (ball.radius * ball.radius);
        if (d2 >= 1) continue;
        double nz = std::sqrt(1 - d2);
        double nx = dx / ball.radius, ny = dy / ball.radius;
        double diffuse = std::max(0.0, -0.5 * nx - 0.6 * ny + 0.62 * nz);
        double spec = std::pow(std::max(0.0, -0.35 * nx - 0.45 * ny + 0.82 * nz), 40);
        r = ball.r * (0.15 + 0.85 * diffuse) + 255 * spec;
        g = ball.g * (0.15 + 0.85 * diffuse) + 255 * spec;
        b = ball.b * (0.15 + 0.85 * diffuse) + 255 * spec;
      }
      double noise = (unitNoise(x, y, 7) - 0.5) * 8;
      put(im, x, y, r + noise, g + noise, b + noise);
    }
  return im;
}

// ---- error measurement ----
struct ErrorSum {
  double squared = 0;
  double samples = 0;
  double mse() const { return samples > 0 ? squared / samples : 0; }
  double psnr() const { return mse() > 0 ? 10 * std::log10(255.0 * 255.0 / mse()) : INFINITY; }
};

// Compares each quantized row with the original as it arrives. Besides the
// plain error it measures the error after a 3x3 box blur of both pictures, a
// crude stand-in for the eye's low-pass: dithering raises the plain MSE but
// should lower the blurred one. Keeps three quantized rows, nothing more.
class ErrorSink final : public lattice::IndexedSink {
 public:
  ErrorSink(const RgbImage& original, int colors) : original_(original), colors_(colors) {}
  int maxColors() const override { return colors_; }
  void begin(const lattice::FrameInfo& frame) override {
    palette_ = frame.palette;
    for (auto& r : rows_) r.assign(static_cast<std::size_t>(frame.width) * 3, 0);
  }
  void row(int y, std::span<const lattice::PaletteIndex> indices) override {
    std::vector<int>& out = rows_[static_cast<std::size_t>(y) % 3];
    for (std::size_t x = 0; x < indices.size(); ++x) {
      const std::uint8_t* p = original_.pixel(int(x), y);
      lattice::Rgb8 c = palette_[indices[x]];
      out[3 * x] = c.r;
      out[3 * x + 1] = c.g;
      out[3 * x + 2] = c.b;
      double dr = p[0] - c.r, dg = p[1] - c.g, db = p[2] - c.b;
      error.squared += dr * dr + dg * dg + db * db;
      error.samples += 3;
    }
    if (y >= 1) blurredRow(y - 1, y);
  }
  void end() override { blurredRow(original_.height - 1, original_.height - 1); }
  ErrorSum error, blurred;

 private:
  // Blurred error of row yc, given rows up to `last` (clamped at the edges).
  void blurredRow(int yc, int last) {
    const int w = original_.width;
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double q = 0, o = 0;
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int yy = std::clamp(yc + dy, 0, last), xx = std::clamp(x + dx, 0, w - 1);
            q += rows_[static_cast<std::size_t>(yy) % 3][static_cast<std::size_t>(3 * xx + ch)];
            o += original_.pixel(xx, yy)[ch];
            ++n;
          }
        double d = (q - o) / n;
        blurred.squared += d * d;
        blurred.samples += 1;
      }
  }
  const RgbImage& original_;
  int colors_;
  lattice::Palette palette_;
  std::array<std::vector<int>, 3> rows_;
};

ErrorSum blurredCompare(const RgbImage& a, const RgbImage& b) {
  ErrorSum e;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double d = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int yy = std::clamp(y + dy, 0, a.height - 1), xx = std::clamp(x + dx, 0, a.width - 1);
            d += double(a.pixel(xx, yy)[ch]) - double(b.pixel(xx, yy)[ch]);
          }
        d /= 9;
        e.squared += d * d;
        e.samples += 1;
      }
  return e;
}

ErrorSum compare(const RgbImage& a, const RgbImage& b) {
  ErrorSum e;
  for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i) {
    double d = double(a.rgb[i]) - double(b.rgb[i]);
    e.squared += d * d;
    e.samples += 1;
  }
  return e;
}

ErrorSum eighteenBitFloor(const RgbImage& image) {
  ErrorSum e;
  for (std::uint8_t v : image.rgb) {
    double d = double(v) - lattice::expand6to8(lattice::reduce8to6(v));
    e.squared += d * d;
    e.samples += 1;
  }
  return e;
}

struct Config {
  std::string name;
  lattice::quantize::QuantizeOptions options;
  lattice::quantize::PipelineMode mode = lattice::quantize::PipelineMode::TwoPass;
};

std::vector<Config> configs() {
  using lattice::quantize::Dither;
  using lattice::quantize::SplitRule;
  std::vector<Config> list;
  auto add = [&](std::string name, lattice::quantize::SplitRule split, int refine, lattice::quantize::Dither dither) {
    lattice::quantize::QuantizeOptions o;
    o.split = split;
    o.refineIterations = refine;
    o.dither = dither;
    list.push_back({std::move(name), o});
  };
  add("median", lattice::quantize::SplitRule::Median, 0, lattice::quantize::Dither::None);
  add("variance", lattice::quantize::SplitRule::Variance, 0, lattice::quantize::Dither::None);
  add("median + refine 3", lattice::quantize::SplitRule::Median, 3, lattice::quantize::Dither::None);
  add("variance + refine 3", lattice::quantize::SplitRule::Variance, 3, lattice::quantize::Dither::None);
  add("median, fs", lattice::quantize::SplitRule::Median, 0, lattice::quantize::Dither::FloydSteinberg);
  add("median, bayer", lattice::quantize::SplitRule::Median, 0, lattice::quantize::Dither::Bayer);
  add("variance + refine 3, fs", lattice::quantize::SplitRule::Variance, 3, lattice::quantize::Dither::FloydSteinberg);
  return list;
}

struct Result {
  ErrorSum error, blurred;
  double milliseconds = 0;
  long long peakBytes = 0;
};

Result runOurs(const RgbImage& image, int k, const Config& config, int repeats) {
  Result result;
  result.milliseconds = INFINITY;
  for (int i = 0; i < repeats; ++i) {
    lattice::RgbImageSource source(image);
    ErrorSink sink(image, k);
    lattice::quantize::PipelineOptions options;
    options.mode = config.mode;
    options.quantize = config.options;
    options.progress = false;
    long long before = liveBytes.load();
    peakBytes = before;
    auto start = std::chrono::steady_clock::now();
    lattice::quantize::runPipeline(source, sink, options);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.milliseconds = std::min(result.milliseconds, ms);
    result.peakBytes = peakBytes.load() - before;
    result.error = sink.error;
    result.blurred = sink.blurred;
  }
  return result;
}

std::string findPngquant() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"}) {
    std::filesystem::path p = std::filesystem::path(dir) / "pngquant";
    if (std::filesystem::exists(p)) return p.string();
  }
  return {};
}

// Runs pngquant as a child; false if it failed. Peak RSS from wait4.
bool runPngquant(const std::string& exe, const std::filesystem::path& in, const std::filesystem::path& out, int k,
                 bool dither, Result& result) {
  std::vector<std::string> args{exe, "--force", "--speed", "1", dither ? "--floyd=1" : "--nofs", "--output",
                                out.string(), std::to_string(k), in.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return false;
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) < 0) return false;
  result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.peakBytes = static_cast<long long>(usage.ru_maxrss) * 1024;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void printRow(const std::string& image, int k, const std::string& method, const Result& r) {
  fmt::print("| {} | {} | {} | {:.1f} | {:.2f} | {:.1f} | {:.1f} | {} |\n", image, k, method, r.error.mse(),
             r.error.psnr(), r.blurred.mse(), r.milliseconds, (r.peakBytes + 1023) / 1024);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::filesystem::path keep;
  std::vector<std::pair<std::string, RgbImage>> images;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--quick") {
      quick = true;
    } else if (arg == "--keep" && i + 1 < argc) {
      keep = argv[++i];
    } else if (arg == "--help" || arg == "-h") {
      fmt::print("usage: quantize_bench [--quick] [--keep DIR] [extra.png ...]\n");
      return 0;
    } else {
      try {
        images.emplace_back(std::filesystem::path(arg).filename().string(), lattice::io::readPng(arg));
      } catch (const std::exception& e) {
        fmt::print(stderr, "quantize_bench: {}\n", e.what());
        return 3;
      }
    }
  }
  const int w = quick ? 160 : 640, h = quick ? 120 : 480;
  images.insert(images.begin(), {"still life", makeStillLife(w, h)});
  images.insert(images.begin(), {"landscape", makeLandscape(w, h)});
  const int repeats = quick ? 1 : 3;

  std::filesystem::path work = keep.empty() ? std::filesystem::temp_directory_path() /
                                                  fmt::format("quantize_bench_{}", getpid())
                                            : keep;
  std::filesystem::create_directories(work);
  std::string pngquant = findPngquant();
  if (pngquant.empty()) fmt::print("pngquant not found: skipping its rows (apt-get install pngquant)\n\n");

  fmt::print("| image | K | method | MSE | PSNR dB | blurred MSE | ms | peak KiB |\n|---|---|---|---|---|---|---|---|\n");
  for (std::size_t index = 0; index < images.size(); ++index) {
    const auto& [name, image] = images[index];
    std::filesystem::path input = work / fmt::format("input_{}.png", index);
    lattice::io::writePng(input, image);
    ErrorSum floor = eighteenBitFloor(image);
    fmt::print("| {} {}x{} | - | 18-bit floor (6 bits/channel, no palette) | {:.1f} | {:.2f} | | | |\n", name,
               image.width, image.height, floor.mse(), floor.psnr());
    for (int k : {8, 16, 256}) {
      for (const Config& config : configs()) printRow(name, k, config.name, runOurs(image, k, config, repeats));
      if (!pngquant.empty())
        for (bool dither : {false, true}) {
          Result r;
          std::filesystem::path out = work / fmt::format("pngquant_{}_{}_{}.png", index, k, dither ? "fs" : "nofs");
          if (!runPngquant(pngquant, input, out, k, dither, r)) {
            fmt::print("| {} | {} | pngquant {} | failed | | | | |\n", name, k, dither ? "--floyd=1" : "--nofs");
            continue;
          }
          RgbImage quantized = lattice::io::readPng(out);
          r.error = compare(image, quantized);
          r.blurred = blurredCompare(image, quantized);
          printRow(name, k, dither ? "pngquant --speed 1 --floyd=1" : "pngquant --speed 1 --nofs", r);
        }
    }
    // Pipeline modes at K = 256 (same palette for passes and frame).
    for (auto [mode, label] : {std::pair{lattice::quantize::PipelineMode::TwoPass, "mode passes"},
                               std::pair{lattice::quantize::PipelineMode::Frame, "mode frame"},
                               std::pair{lattice::quantize::PipelineMode::Sample, "mode sample 4"}}) {
      Config c{label, {}, mode};
      printRow(name, 256, label, runOurs(image, 256, c, repeats));
    }
  }
  if (keep.empty()) std::filesystem::remove_all(work);
  return 0;
}
