// wire_search_bench SCENE.toml [--size WxH] [--repeat N] [--limits A,B,...] [--profile strict|compact]
//
// The wire budget's search (app/wire_budget.hpp) on one core: the scene is
// rendered once as `lattice render` renders it (double, lattices), then for
// each byte limit the coarse-to-fine search runs N times (its median wall
// time) and the exhaustive search (every setting searched whole) once, on
// the Tek 4125 (strict unless --profile) with the screen set to the picture and the forms a
// budget turns on, as `lattice render --wire-bytes` does. Prints one
// tab-separated row a search:
//   limit mode colours dither lambda bytes psnr encodings proxy_encodings seconds cpu_seconds
// (wall and CPU seconds: the medians for the coarse-to-fine runs), so the proxy's loss against the exhaustive search and the time saved are
// read side by side. bench/wire-search.sh runs it.
#include <fmt/format.h>

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "app/wire_budget.hpp"
#include "bench/bench_main.hpp"
#include "devices/device_table.hpp"
#include "foundation/error.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"

namespace {

using namespace lattice;

// The process's CPU seconds: the search is single-threaded, so this is its
// time on one core, which a busy machine inflates far less than wall time.
double cpuSeconds() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

void row(std::uint64_t limit, const char* mode, const app::WireSearch& s, double seconds, double cpu) {
  const app::WireChoice& c = s.choice;
  std::printf("%llu\t%s\t%d\t%s\t%.0f\t%llu\t%.2f\t%d\t%d\t%.3f\t%.3f\n", static_cast<unsigned long long>(limit),
              mode, c.colors, c.dither == quantize::Dither::None ? "none" : "fs", c.lambda,
              static_cast<unsigned long long>(c.bytes), c.psnr, s.encodings, s.proxyEncodings, seconds, cpu);
  std::fflush(stdout);
}

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const char* usage =
      "usage: wire_search_bench SCENE.toml [--size WxH] [--repeat N] [--limits A,B,...] [--profile strict|compact]";
  std::string scene, profile = "strict";
  int width = 512, height = 512, repeat = 5;
  std::vector<std::uint64_t> limits = {57600, 76800};
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--size" && i + 1 < args.size()) {
      if (std::sscanf(args[++i].c_str(), "%dx%d", &width, &height) != 2) throw Error(ErrorKind::Usage, usage);
    } else if (args[i] == "--repeat" && i + 1 < args.size()) {
      repeat = std::max(1, std::stoi(args[++i]));
    } else if (args[i] == "--profile" && i + 1 < args.size()) {
      profile = args[++i];
    } else if (args[i] == "--limits" && i + 1 < args.size()) {
      limits.clear();
      std::stringstream list(args[++i]);
      for (std::string item; std::getline(list, item, ',');) limits.push_back(std::stoull(item));
    } else if (scene.empty()) {
      scene = args[i];
    } else {
      throw Error(ErrorKind::Usage, usage);
    }
  }
  if (scene.empty()) throw Error(ErrorKind::Usage, usage);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.threads = 1;
  lht::SceneWithLattices loaded = lht::loadSceneWithLattices(scene);
  Renderer<double> renderer(loaded.scene, settings);
  const RgbImage reference = renderImage(renderer);
  std::vector<std::string> keys = {"profile=" + profile, fmt::format("width={}", width), fmt::format("height={}", height)};
  for (const std::string& s : app::wireSettingsToAdd(devices::makeDevice("tek4125", keys), keys)) keys.push_back(s);
  const devices::Device device = devices::makeDevice("tek4125", keys);
  std::printf("limit\tmode\tcolours\tdither\tlambda\tbytes\tpsnr\tencodings\tproxy_encodings\tseconds\tcpu_seconds\n");
  for (std::uint64_t limit : limits) {
    app::WireBudget budget;
    budget.bytes = limit;
    std::vector<double> times, cpu;
    app::WireSearch fast;
    for (int i = 0; i < repeat; ++i) {
      const double start = cpuSeconds();
      fast = app::searchWireBudget(reference, device, budget, {}, false);
      cpu.push_back(cpuSeconds() - start);
      times.push_back(fast.seconds);
    }
    std::sort(times.begin(), times.end());
    std::sort(cpu.begin(), cpu.end());
    row(limit, "coarse-to-fine", fast, times[times.size() / 2], cpu[cpu.size() / 2]);
    budget.exhaustive = true;
    const double start = cpuSeconds();
    const app::WireSearch every = app::searchWireBudget(reference, device, budget, {}, false);
    row(limit, "exhaustive", every, every.seconds, cpuSeconds() - start);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return lattice::bench::runBenchMain("wire_search_bench", [&] { return run(argc, argv); });
}
