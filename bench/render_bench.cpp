// Render benchmark: the whole ray tracer (camera, CSG + BVH, quartic and
// lattice leaves, eq. 2.3 with shadow rays) on the example scenes.
//
// Part 1, for every scene given: Renderer<double> and Renderer<float> on 1
// and 2 threads, median render time of --runs runs, rays per second (primary
// plus shadow rays, as Renderer::raysTraced counts them), and how far the
// float picture is from the double one (8-bit images: PSNR, largest channel
// difference, share of pixels that differ at all).
//
// Part 2, the thesis's Table 3 question (Lewis 1988, sec. 4): a lattice
// scene rendered with its lattices (the default) and as a "full ray trace"
// (BuildOptions::fullRayTrace: every lattice replaced by the CSG object it was
// rasterized from), at --full-size, side by side: medians and their ratio.
//
// Scene set-up (parsing, building the tree, rasterizing a lattice's table) is
// done once per scene and reported apart ("setup_ms"): it is not per-frame
// work. Usage:
//   render_bench [--runs R] [--threads-list 1,2] [--arith both|double|float]
//                [--full-size N] [--full-threads N] [--full-scene FILE]... SCENE.toml...
#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "io/png.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"
#include "foundation/error.hpp"

using namespace lattice;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// CPU seconds of the whole process (all threads): unlike wall time it hardly
// grows when other jobs share the machine, so it is the steadier figure there.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Timing {
  double medianSeconds = 0;
  double medianCpuSeconds = 0;
  double raysPerRender = 0;  // primary + shadow rays of one render
  RgbImage image;            // the last run's picture
};

// Renders `runs` times with one Renderer (built outside the timed region) and
// keeps the median. Every run renders every pixel again: renderImage does not
// cache, it calls rowLinear for each row.
template <typename T>
Timing timeRenders(const SceneDesc& scene, const RenderSettings& settings, int runs) {
  Renderer<T> renderer(scene, settings);
  Timing timing;
  std::vector<double> seconds, cpu;
  for (int r = 0; r < runs; ++r) {
    const std::uint64_t before = renderer.raysTraced();
    const double cpuStart = processCpuSeconds();
    const auto start = Clock::now();
    timing.image = renderImage(renderer);
    seconds.push_back(secondsSince(start));
    cpu.push_back(processCpuSeconds() - cpuStart);
    timing.raysPerRender = static_cast<double>(renderer.raysTraced() - before);
  }
  timing.medianSeconds = median(seconds);
  timing.medianCpuSeconds = median(cpu);
  return timing;
}

struct ImageDifference {
  double psnr = 0;  // dB over all channels; infinite when identical
  int maxChannel = 0;
  double differingPixelsPercent = 0;
};

ImageDifference compare(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error(ErrorKind::Internal, "render_bench: float and double pictures differ in size");
  ImageDifference d;
  double sumSquares = 0;
  std::size_t differing = 0;
  const std::size_t pixels = a.rgb.size() / 3;
  for (std::size_t p = 0; p < pixels; ++p) {
    bool differs = false;
    for (std::size_t c = 0; c < 3; ++c) {
      const int delta = std::abs(int(a.rgb[3 * p + c]) - int(b.rgb[3 * p + c]));
      d.maxChannel = std::max(d.maxChannel, delta);
      sumSquares += double(delta) * double(delta);
      differs = differs || delta != 0;
    }
    differing += differs ? 1 : 0;
  }
  const double mse = pixels ? sumSquares / double(3 * pixels) : 0;
  d.psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : INFINITY;
  d.differingPixelsPercent = pixels ? 100.0 * double(differing) / double(pixels) : 0;
  return d;
}

std::string formatPsnr(double psnr) { return std::isinf(psnr) ? std::string("identical") : fmt::format("{:.1f}", psnr); }

std::vector<int> parseThreadList(const std::string& text) {
  std::vector<int> list;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const int n = std::atoi(item.c_str());
    if (n < 1 || n > 256) throw Error(ErrorKind::Usage, fmt::format("--threads-list: '{}' is not a thread count 1..256", item));
    list.push_back(n);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return list;
}

void printSceneHeader() {
  fmt::print("{:<20} {:>9} {:>3} {:>9} {:>10} {:>10} {:>10} {:>6} {:>10} {:>10} {:>10} {:>9} {:>7}\n", "scene",
             "size", "thr", "setup_ms", "double_ms", "dbl_cpu_ms", "float_ms", "f/d", "rays", "dbl_Mray/s",
             "flt_Mray/s", "psnr_dB", "maxdiff");
}

// Which scalar types part 1 renders; "double" alone serves bench/povray-peer.sh,
// which wants Lattice's render time of a scene next to POV-Ray's trace time.
enum class ArithChoice { Both, Double, Float };

void benchScene(const std::filesystem::path& file, const std::vector<int>& threadList, int runs, ArithChoice arith) {
  const auto setupStart = Clock::now();
  const SceneDesc scene = lht::loadSceneWithLattices(file).scene;
  // The first Renderer rasterizes any lattice (once per loaded scene, the
  // table is shared); do it here so that no timed render pays for it.
  { const Renderer<double> warm(scene, RenderSettings{1, 1, 1, {}}); }
  const double setup = secondsSince(setupStart);

  for (int threads : threadList) {
    RenderSettings settings;
    settings.threads = threads;
    if (arith == ArithChoice::Double || arith == ArithChoice::Float) {
      const Timing t = arith == ArithChoice::Double ? timeRenders<double>(scene, settings, runs)
                                                    : timeRenders<float>(scene, settings, runs);
      const double ms = t.medianSeconds * 1e3, mrays = t.raysPerRender / t.medianSeconds / 1e6;
      const bool isDouble = arith == ArithChoice::Double;
      fmt::print("{:<20} {:>9} {:>3} {:>9.1f} {:>10} {:>10} {:>10} {:>6} {:>10.0f} {:>10} {:>10} {:>9} {:>7}\n",
                 file.stem().string(), fmt::format("{}x{}", t.image.width, t.image.height), threads, setup * 1e3,
                 isDouble ? fmt::format("{:.1f}", ms) : "-",
                 isDouble ? fmt::format("{:.1f}", t.medianCpuSeconds * 1e3) : "-",
                 isDouble ? "-" : fmt::format("{:.1f}", ms), "-",
                 t.raysPerRender, isDouble ? fmt::format("{:.2f}", mrays) : "-",
                 isDouble ? "-" : fmt::format("{:.2f}", mrays), "-", "-");
      std::fflush(stdout);
      continue;
    }
    const Timing d = timeRenders<double>(scene, settings, runs);
    const Timing f = timeRenders<float>(scene, settings, runs);
    const ImageDifference diff = compare(d.image, f.image);
    fmt::print(
        "{:<20} {:>9} {:>3} {:>9.1f} {:>10.1f} {:>10.1f} {:>10.1f} {:>6.2f} {:>10.0f} {:>10.2f} {:>10.2f} {:>9} {:>7}\n",
        file.stem().string(), fmt::format("{}x{}", d.image.width, d.image.height), threads, setup * 1e3,
        d.medianSeconds * 1e3, d.medianCpuSeconds * 1e3, f.medianSeconds * 1e3, f.medianSeconds / d.medianSeconds, d.raysPerRender,
               d.raysPerRender / d.medianSeconds / 1e6, f.raysPerRender / f.medianSeconds / 1e6,
               formatPsnr(diff.psnr), diff.maxChannel);
    std::fflush(stdout);
  }
}

// Lattices against their exact objects (the thesis's "full ray trace").
void benchFullRayTrace(const std::filesystem::path& file, int size, int threads, int runs) {
  const SceneDesc scene = lht::loadSceneWithLattices(file).scene;
  RenderSettings lattice;
  lattice.width = lattice.height = size;
  lattice.threads = threads;
  RenderSettings full = lattice;
  full.build.fullRayTrace = true;
  { const Renderer<double> warm(scene, lattice); }  // rasterize the table untimed
  auto timeBuild = [&](const RenderSettings& settings) {
    const auto start = Clock::now();
    const Renderer<double> renderer(scene, settings);
    return secondsSince(start);
  };
  const double latticeBuild = timeBuild(lattice), fullBuild = timeBuild(full);
  const Timing l = timeRenders<double>(scene, lattice, runs);
  const Timing f = timeRenders<double>(scene, full, runs);
  const ImageDifference diff = compare(l.image, f.image);
  fmt::print("{:<20} {:>9} {:>3} {:>10.1f} {:>10.1f} {:>10.1f} {:>10.1f} {:>6.2f} {:>10.1f} {:>10.1f} {:>6.2f} {:>9} {:>8.1f}\n",
             file.stem().string(), fmt::format("{}x{}", size, size), threads, latticeBuild * 1e3, fullBuild * 1e3,
             l.medianSeconds * 1e3, f.medianSeconds * 1e3, f.medianSeconds / l.medianSeconds,
             l.medianCpuSeconds * 1e3, f.medianCpuSeconds * 1e3, f.medianCpuSeconds / l.medianCpuSeconds,
             formatPsnr(diff.psnr), diff.differingPixelsPercent);
  std::fflush(stdout);
}

int usage(const std::string& problem) {
  fmt::print(stderr,
             "render_bench: {}\n"
             "usage: render_bench [--runs R] [--threads-list 1,2] [--arith both|double|float] [--full-size N]\n"
             "                    [--full-threads N]\n"
             "                    [--full-scene FILE]... SCENE.toml...\n",
             problem);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> scenes, fullScenes;
  std::vector<int> threadList{1, 2};
  int runs = 5, fullSize = 512, fullThreads = 2;
  ArithChoice arith = ArithChoice::Both;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      const bool hasValue = i + 1 < argc;
      if (a == "--runs" && hasValue)
        runs = std::atoi(argv[++i]);
      else if (a == "--threads-list" && hasValue)
        threadList = parseThreadList(argv[++i]);
      else if (a == "--arith" && hasValue) {
        const std::string v = argv[++i];
        if (v == "both")
          arith = ArithChoice::Both;
        else if (v == "double")
          arith = ArithChoice::Double;
        else if (v == "float")
          arith = ArithChoice::Float;
        else
          return usage(fmt::format("--arith takes both, double or float, not '{}'", v));
      } else if (a == "--full-size" && hasValue)
        fullSize = std::atoi(argv[++i]);
      else if (a == "--full-threads" && hasValue)
        fullThreads = std::atoi(argv[++i]);
      else if (a == "--full-scene" && hasValue)
        fullScenes.emplace_back(argv[++i]);
      else if (!a.empty() && a[0] != '-')
        scenes.emplace_back(a);
      else
        return usage(fmt::format("unknown or incomplete option '{}'", a));
    }
    if (runs < 1 || runs > 1000) return usage("--runs must be 1..1000");
    if (fullSize < 8 || fullSize > 8192) return usage("--full-size must be 8..8192");
    if (fullThreads < 1 || fullThreads > 256) return usage("--full-threads must be 1..256");
    if (scenes.empty() && fullScenes.empty()) return usage("give at least one scene file");

    fmt::print("# render_bench: median of {} renders per cell; setup (parse, build, rasterize) timed apart\n", runs);
    if (!scenes.empty()) {
      fmt::print("# dbl_cpu_ms: CPU time of the double render, all threads; f/d = float time / double time;\n"
                 "# psnr/maxdiff: float picture against double (8-bit)\n");
      printSceneHeader();
      for (const auto& scene : scenes) benchScene(scene, threadList, runs, arith);
    }
    if (!fullScenes.empty()) {
      fmt::print("\n# lattice vs full ray trace (double); ratio = full / lattice (wall, then CPU time of all threads); "
                 "psnr/differ_%: full picture against lattice picture\n");
      fmt::print("{:<20} {:>9} {:>3} {:>10} {:>10} {:>10} {:>10} {:>6} {:>10} {:>10} {:>6} {:>9} {:>8}\n", "scene",
                 "size", "thr", "lat_build", "full_build", "lattice_ms", "full_ms", "ratio", "lat_cpu", "full_cpu",
                 "ratio", "psnr_dB", "differ_%");
      for (const auto& scene : fullScenes) benchFullRayTrace(scene, fullSize, fullThreads, runs);
    }
  } catch (const Error& e) {
    fmt::print(stderr, "render_bench: {}\n", e.what());
    return static_cast<int>(e.kind());
  } catch (const std::exception& e) {
    fmt::print(stderr, "render_bench: {}\n", e.what());
    return 1;
  }
  return 0;
}
