// The compressed LHT against the hashed one (docs/lattices.md, "The
// compressed LHT"): bytes per entry all-in and look-up speed.
//   build/bench/lht_form_bench [--runs N (7)] [--lookups M (4000000)] [--table1]
//   (from the repository root; bench/lht-compressed.sh runs it)
//
// Method and tunables:
// * Tables: the hair of scenes/fuzzy-sphere-1000.toml at f_lat 1 and 2 (the
//   scene's own [[lattices]] entry), rasterized once, packed in both forms at
//   the thesis's entry precision (and at compact, whose payload is 3 bytes).
//   --table1 adds every row of the thesis's Table 1 (sizes only: the largest
//   rows take a minute to rasterize).
// * Look-ups: M pairs as a render asks them: random lines through the
//   lattice box (a random point inside, a random direction), clipped to the
//   box, both ends rounded to the nearest grid point, asked both ways, as
//   the lattice leaf does (lht/leaf/lattice_leaf.cpp). Fixed seed.
// * Timing: the same look-ups through LhtLookup (what the leaf calls), the two
//   forms alternating, N runs each; the median ns per look-up of each, and
//   their ratio. The load average is printed before and after: the machine
//   may be shared, and alternating keeps the two forms under the same load.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include "foundation/error.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "lht/raster/thesis_table1.hpp"
#include "loader/table_build.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return fmt::format("{} {} {}", a, b, c);
}

struct Pair {
  LatticePoint in, out;
};

std::vector<Pair> renderLikePairs(const LatticeBox& box, std::size_t count) {
  std::mt19937_64 random(1988);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sign(-1.0, 1.0);
  const auto& c = box.cells();
  const Bounds<double> bounds{Vec3d(0.0), Vec3d(c[0], c[1], c[2])};
  std::vector<Pair> pairs;
  pairs.reserve(count);
  const auto round = [&](const Vec3d& p) {
    LatticePoint q;
    std::uint8_t* axis[3] = {&q.x, &q.y, &q.z};
    for (int a = 0; a < 3; ++a) *axis[a] = static_cast<std::uint8_t>(std::clamp(int(std::lround(p[a])), 0, c[a]));
    return q;
  };
  while (pairs.size() < count) {
    const Vec3d origin(unit(random) * c[0], unit(random) * c[1], unit(random) * c[2]);
    const Vec3d direction = glm::normalize(Vec3d(sign(random), sign(random), sign(random)));
    double t0, t1;
    const double inf = std::numeric_limits<double>::infinity();
    if (!bounds.clip(Ray<double>{origin, direction}, -inf, inf, t0, t1)) continue;
    const LatticePoint in = round(origin + direction * t0), out = round(origin + direction * t1);
    if (in == out) continue;
    pairs.push_back({in, out});
    pairs.push_back({out, in});
  }
  pairs.resize(count);
  return pairs;
}

double nsPerLookup(const LhtLookup& lookup, const std::vector<Pair>& pairs, std::uint64_t& sink) {
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t sum = 0;
  for (const Pair& p : pairs)
    if (const std::uint8_t* payload = lookup.payload(p.in, p.out)) sum += payload[0] + 1;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  sink += sum;
  return seconds * 1e9 / double(pairs.size());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Forms {
  LhtFile hashed, compressed;
};

Forms bothForms(const LatticeBox& box, const RasterResult& raster, LhtPrecision precision) {
  Forms f;
  for (LhtFile* file : {&f.hashed, &f.compressed}) {
    file->box = box;
    file->pairs = raster.stats.pairs;
    file->hits = raster.stats.hits;
  }
  f.hashed.table = LatticeHashTable(raster.hits, precision);
  f.compressed.table = CompressedTable(raster.hits, box.cells(), precision);
  return f;
}

void sizeRow(const std::string& name, const LatticeBox& box, const RasterResult& raster, LhtPrecision precision) {
  const Forms f = bothForms(box, raster, precision);
  const CompressedTable& c = f.compressed.compressed();
  const double niz = double(raster.stats.hits), entries = double(raster.hits.size());
  fmt::print("| {} | {} | {}x{}x{} | {} | {} | {:.2f} | {:.2f} | {} ({} + {} + {}) | {:.2f} | {:.2f} | {} |\n", name,
             lhtPrecisionName(precision), box.cells()[0], box.cells()[1], box.cells()[2], raster.stats.hits,
             raster.hits.size(), double(f.hashed.tableBytes()) / entries, double(f.hashed.tableBytes()) / niz,
             c.bytes(), c.bitmapBytes(), c.rankBytes(), c.payloads().size(), double(c.bytes()) / entries,
             double(c.bytes()) / niz, c.layout() == PairLayout::Symmetric ? "symmetric" : "ordered");
}

RasterResult rasterizeQuietly(const LatticeBox& box, const Primitive<double>& object) {
  RasterOptions options;
  options.progress = false;
  return rasterize(box, object, options);
}

}  // namespace

int main(int argc, char** argv) try {
  int runs = 7;
  std::size_t lookups = 4000000;
  bool table1 = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc) runs = std::max(1, std::stoi(argv[++i]));
    else if (arg == "--lookups" && i + 1 < argc) lookups = std::stoull(argv[++i]);
    else if (arg == "--table1") table1 = true;
    else throw Error(ErrorKind::Usage, "usage: lht_form_bench [--runs N] [--lookups M] [--table1]");
  }
  fmt::print("load average before: {}\n\n", loadAverage());
  const SceneWithLattices loaded = loadSceneWithLattices("scenes/fuzzy-sphere-1000.toml");
  const LatticeDefinition& hair = *loaded.lattices.at(0);
  fmt::print("| table | precision | cells | N_iz | entries | hashed B/entry | hashed B/N_iz | compressed bytes "
             "(bitmap + ranks + payloads) | compressed B/entry | compressed B/N_iz | layout |\n");
  fmt::print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  struct Timing {
    std::string name;
    double hashed, compressed;
  };
  std::vector<Timing> timings;
  std::uint64_t sink = 0;
  for (double oversample : {1.0, 2.0}) {
    const LatticeObject object = sceneObject(hair.object, hair.objectText);
    const LatticeBox box(object.bounds, hair.lambda, oversample);
    const RasterResult raster = rasterizeQuietly(box, *object.primitive);
    const std::string name = fmt::format("scene hair, f_lat {:g}", oversample);
    for (LhtPrecision p : {LhtPrecision::Thesis, LhtPrecision::Compact}) sizeRow(name, box, raster, p);
    const Forms f = bothForms(box, raster, LhtPrecision::Thesis);
    const std::vector<Pair> pairs = renderLikePairs(box, lookups);
    const LhtLookup hashed(f.hashed), compressed(f.compressed);
    std::vector<double> th, tc;
    for (int r = 0; r < runs; ++r) {
      th.push_back(nsPerLookup(hashed, pairs, sink));
      tc.push_back(nsPerLookup(compressed, pairs, sink));
    }
    timings.push_back({name, median(th), median(tc)});
  }
  if (table1)
    for (const Table1Row& row : table1Rows()) {
      const LatticeObject object = row.make();
      const LatticeBox box(object.bounds, 1.0, row.oversample);
      const RasterResult raster = rasterizeQuietly(box, *object.primitive);
      sizeRow(fmt::format("Table 1: {} f_lat {:g}", row.object, row.oversample), box, raster, LhtPrecision::Thesis);
    }
  fmt::print("\n{} look-ups a run (render-like pairs), {} runs alternating, median ns per look-up:\n\n", lookups, runs);
  fmt::print("| table | hashed ns | compressed ns | compressed / hashed |\n|---|---:|---:|---:|\n");
  for (const Timing& t : timings)
    fmt::print("| {} | {:.1f} | {:.1f} | {:.3f} |\n", t.name, t.hashed, t.compressed, t.compressed / t.hashed);
  fmt::print("\nload average after: {} (checksum {})\n", loadAverage(), sink);
  return 0;
} catch (const std::exception& e) {
  fmt::print(stderr, "lht_form_bench: {}\n", e.what());
  return 1;
}
