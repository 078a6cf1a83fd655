// Lattice benchmark: rasterization time and table size for Table 1's
// largest fixed-geometry row, and for the fuzzy sphere (thesis sec. 3.4) at
// f_lat 1 and 2: table build time and bytes, render time of the lattice
// scene vs the full ray trace of the same scene, and the image error.
//   build/bench/lattice_bench [scene] [width]     (from the repository root)
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "loader/lattice_scene_loader.hpp"
#include "loader/table_build.hpp"
#include "lht/raster/thesis_table1.hpp"
#include "render/renderer.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Timed {
  RgbImage image;
  double buildSeconds = 0.0;
  double renderSeconds = 0.0;
};

Timed renderScene(const SceneDesc& scene, bool full, int width) {
  RenderSettings settings;
  settings.width = width;
  settings.height = width;
  settings.build.fullRayTrace = full;
  Timed t;
  auto start = std::chrono::steady_clock::now();
  Renderer<double> renderer(scene, settings);  // builds the tree (and rasterizes the lattice)
  t.buildSeconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  t.image = renderImage(renderer);
  t.renderSeconds = secondsSince(start);
  return t;
}

void imageError(const RgbImage& a, const RgbImage& b, double& rms, double& differing, double& blockWorst) {
  double sum = 0.0;
  long diff = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    bool any = false;
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.rgb[i + c]) - double(b.rgb[i + c]);
      sum += d * d;
      any = any || d != 0.0;
    }
    diff += any;
  }
  rms = std::sqrt(sum / double(a.rgb.size()));
  differing = double(diff) / double(a.width * a.height);
  blockWorst = 0.0;
  for (int by = 0; by + 8 <= a.height; by += 8)
    for (int bx = 0; bx + 8 <= a.width; bx += 8) {
      double sa = 0.0, sb = 0.0;
      for (int y = by; y < by + 8; ++y)
        for (int x = bx; x < bx + 8; ++x)
          for (int c = 0; c < 3; ++c) {
            const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 3 + c;
            sa += a.rgb[i];
            sb += b.rgb[i];
          }
      blockWorst = std::max(blockWorst, std::abs(sa - sb) / (8 * 8 * 3));
    }
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string sceneFile = argc > 1 ? argv[1] : "scenes/fuzzy-sphere-1000.toml";
  const int width = argc > 2 ? std::atoi(argv[2]) : 256;

  fmt::print("Table 1 rows (rasterization, all cores):\n");
  for (const Table1Row& row : table1Rows()) {
    if (row.object != "straight line length 100" && row.object != "hair") continue;
    RasterOptions options;
    options.progress = false;
    const LatticeObject object = row.make();
    const LatticeBox box(object.bounds, 1.0, row.oversample);
    const RasterResult raster = rasterize(box, object, options);
    const LatticeHashTable table(raster.hits);
    fmt::print("  {:<26} f_lat {:g}: N_lp {:>9} N_iz {:>8} traced {:>9}  {:>8.0f} ms  entries {:>8} bytes {:>9} "
               "({:.2f} B/entry, load {:.2f})\n",
               row.object, row.oversample, raster.stats.pairs, raster.stats.hits, raster.stats.traced,
               raster.stats.buildMs, table.entryCount(), table.bytes(), table.bytesPerEntry(), table.loadFactor());
  }

  std::ifstream in(sceneFile);
  if (!in) throw Error(ErrorKind::Input, fmt::format("{}: cannot read the scene", sceneFile));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  fmt::print("\n{} at {}x{}:\n", sceneFile, width, width);
  const SceneDesc fullScene = parseSceneWithLattices(text, sceneFile).scene;
  const Timed full = renderScene(fullScene, true, width);
  fmt::print("  full ray trace:  build {:6.2f} s  render {:7.2f} s\n", full.buildSeconds, full.renderSeconds);
  for (int f : {1, 2}) {
    std::string variant = text;
    const auto at = variant.find("oversample = 1");
    if (at == std::string::npos) throw Error(ErrorKind::Input, "the scene's [[lattices]] needs `oversample = 1`");
    variant.replace(at, 14, fmt::format("oversample = {}", f));
    const SceneWithLattices loaded = parseSceneWithLattices(variant, sceneFile);
    const SceneDesc& scene = loaded.scene;
    // The table alone (the renderer's build below rasterizes it again, timed with the tree).
    if (loaded.lattices.empty()) throw Error(ErrorKind::Input, "the scene defines no [[lattices]]");
    TableSettings quiet;
    quiet.progress = false;
    const BuiltTable built = buildLatticeTable(*loaded.lattices.front(), quiet);
    const LhtFile& lht = built.lht;
    const RasterStats& stats = built.stats;
    const Timed lattice = renderScene(scene, false, width);
    double rms, differing, block;
    imageError(lattice.image, full.image, rms, differing, block);
    fmt::print("  lattice f_lat {}: cells {}x{}x{}  N_lp {}  N_iz {}  entries {}  table {} bytes ({:.2f} B/entry)  "
               "rasterize {:.0f} ms\n",
               f, lht.box.cells()[0], lht.box.cells()[1], lht.box.cells()[2], lht.pairs, lht.hits,
               lht.hashed().entryCount(), lht.hashed().bytes(), lht.hashed().bytesPerEntry(), stats.buildMs);
    fmt::print("                   build {:6.2f} s  render {:7.2f} s ({:.2f}x the full trace)  image vs full: "
               "{:.1f}% pixels differ, RMS {:.1f}/255, worst 8x8 block {:.1f}/255\n",
               lattice.buildSeconds, lattice.renderSeconds, lattice.renderSeconds / full.renderSeconds,
               100.0 * differing, rms, block);
  }
  return 0;
} catch (const std::exception& e) {
  fmt::print(stderr, "lattice_bench: {}\n", e.what());
  return 1;
}
