// Rasterizing one [[lattices]] entry of a scene, timed in the process: no
// scene loading, table or file around it, so a profile of this program is the
// rasterizer's alone, and its timer reads to the microsecond where
// `lattice rasterize --stats` prints whole milliseconds.
//
// Method: the entry's object and box as a scene load builds them
// (lht::sceneObject, LatticeBox); R rasterizations on T threads; the median
// and least of the rasterizer's own wall timer, the median CPU of the
// process over each (std::clock, every thread's), and the counts it made.
//   build/bench/raster_bench SCENE NAME [--runs R] [--threads T] [--oversample F]
#include <fmt/format.h>

#include <algorithm>
#include <ctime>
#include <string>
#include <vector>

#include "bench/bench_main.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/rasterize.hpp"
#include "loader/lattice_scene_loader.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  return bench::runBenchMain("raster_bench", [&] {
    if (argc < 3) throw Error(ErrorKind::Usage, "usage: raster_bench SCENE NAME [--runs R] [--threads T] [--oversample F]");
    const std::string sceneFile = argv[1], name = argv[2];
    int runs = 21;
    unsigned threads = 1;
    double oversample = 0.0;  // 0: the entry's
    for (int a = 3; a < argc; a += 2) {
      const std::string flag = argv[a];
      if (a + 1 >= argc) throw Error(ErrorKind::Usage, fmt::format("raster_bench: {} needs a value", flag));
      if (flag == "--runs") runs = std::max(1, std::stoi(argv[a + 1]));
      else if (flag == "--threads") threads = static_cast<unsigned>(std::stoul(argv[a + 1]));
      else if (flag == "--oversample") oversample = std::stod(argv[a + 1]);
      else throw Error(ErrorKind::Usage, fmt::format("raster_bench: unknown flag {}", flag));
    }
    const SceneWithLattices loaded = loadSceneWithLattices(sceneFile);
    const auto it = std::find_if(loaded.lattices.begin(), loaded.lattices.end(),
                                 [&](const auto& d) { return d->name == name; });
    if (it == loaded.lattices.end())
      throw Error(ErrorKind::Input, fmt::format("{}: no [[lattices]] entry named '{}'", sceneFile, name));
    const LatticeDefinition& def = **it;
    const LatticeObject object = sceneObject(def.object, def.objectText);
    const LatticeBox box(object.bounds, def.lambda, oversample > 0.0 ? oversample : def.oversample);

    RasterOptions options;
    options.progress = false;
    options.threads = threads;
    std::vector<double> wall, cpu;
    RasterStats stats;
    for (int r = 0; r < runs; ++r) {
      const std::clock_t start = std::clock();
      const RasterResult result = rasterize(box, object, options);
      cpu.push_back(1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC);
      wall.push_back(result.stats.buildMs);
      stats = result.stats;
    }
    const auto cells = box.cells();
    fmt::print("{} {}: cells {}x{}x{}; pairs={} distinct={} traced={} hits={}\n", sceneFile, name, cells[0], cells[1],
               cells[2], stats.pairs, stats.distinctPairs, stats.traced, stats.hits);
    fmt::print("{} thread(s), {} runs: wall median {:.3f} ms (least {:.3f}), CPU median {:.3f} ms\n", threads, runs,
               median(wall), *std::min_element(wall.begin(), wall.end()), median(cpu));
    return 0;
  });
}
