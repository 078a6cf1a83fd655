// `lattice rasterize`: builds a lattice hash table (thesis sec. 2.1) for a
// shape or for a [[lattices]] entry of a scene and writes it as a .lht file.
#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "app/commands.hpp"
#include "lht/lattice_object.hpp"
#include "lht/lattice_scene.hpp"
#include "lht/lht_file.hpp"
#include "foundation/error.hpp"

namespace {

using namespace lattice;
using namespace lattice::lht;

struct RasterizeArgs {
  std::string scene, name, shape, output;
  double radius = 0.5, length = 10.0, oversample = 1.0;
  bool stats = false;
  bool oversampleGiven = false;
  std::string precision;  // empty: the scene's, or the thesis's for --shape
  unsigned threads = 0;
};

void printStats(const LhtFile& lht, const RasterStats& stats) {
  fmt::print("pairs={} hits={} entries={} bytes={} precision={} build_ms={:.0f}\n", lht.pairs, lht.hits,
             lht.table.entryCount(), lht.table.bytes(), lhtPrecisionName(lht.table.precision()), stats.buildMs);
}

void runRasterize(const RasterizeArgs& args) {
  const bool fromScene = !args.scene.empty();
  if (fromScene == !args.shape.empty())
    throw Error(ErrorKind::Usage, "rasterize needs either --scene FILE --name NAME or --shape sphere|capsule");
  std::optional<LhtPrecision> precision;
  if (!args.precision.empty()) precision = parseLhtPrecision(args.precision, "--precision");
  LhtFile lht;
  RasterStats stats;
  if (fromScene) {
    if (args.name.empty()) throw Error(ErrorKind::Usage, "--scene needs --name NAME, the [[lattices]] entry to rasterize");
    std::vector<LatticeDefinitionPtr> defs = loadLatticeDefinitions(args.scene);
    const auto it = std::find_if(defs.begin(), defs.end(), [&](const auto& d) { return d->name == args.name; });
    if (it == defs.end()) {
      std::string names;
      for (const auto& d : defs) names += (names.empty() ? "" : ", ") + d->name;
      throw Error(ErrorKind::Input, fmt::format("{}: no [[lattices]] entry named '{}' (defined: {})", args.scene,
                                                args.name, names.empty() ? "none" : names));
    }
    LatticeDefinition& def = **it;
    if (args.oversampleGiven) def.oversample = args.oversample;  // --oversample overrides the scene
    if (precision) def.precision = *precision;                    // and so does --precision
    lht = def.rasterizeNow(true, &stats, args.threads);
  } else {
    LatticeObject object;
    if (args.shape == "sphere")
      object = sphereObject(args.radius);
    else if (args.shape == "capsule")
      object = capsuleObject(args.radius, args.length);
    else
      throw Error(ErrorKind::Usage, fmt::format("unknown --shape '{}'; use sphere or capsule", args.shape));
    lht.box = LatticeBox(object.bounds, 1.0, args.oversample);
    RasterOptions options;
    options.threads = args.threads;
    const RasterResult raster = rasterize(lht.box, *object.primitive, options);
    stats = raster.stats;
    lht.objectHash = object.hash();
    lht.pairs = stats.pairs;
    lht.hits = stats.hits;
    lht.table = LatticeHashTable(raster.hits, precision.value_or(LhtPrecision::Thesis));
  }
  writeLhtFile(args.output, lht);
  if (args.stats) printStats(lht, stats);
}

}  // namespace

namespace lattice::app {

void addRasterize(CLI::App& root) {
  auto args = std::make_shared<RasterizeArgs>();
  auto* cmd = root.add_subcommand(
      "rasterize",
      "Rasterize an object into a lattice hash table (.lht): trace every pair of lattice points\n"
      "(p_i, p_o) on the lattice box and keep the hit closest to p_i (thesis sec. 2.1). Lengths are in\n"
      "units of the grid spacing lambda. Examples:\n"
      "  lattice rasterize --shape sphere --radius 0.5 --oversample 2 -o sphere.lht --stats\n"
      "  lattice rasterize --shape capsule --length 10 --radius 0.5 -o line.lht\n"
      "  lattice rasterize --scene scenes/fuzzy-sphere-1000.toml --name hair -o hair.lht\n"
      "  lattice rasterize --shape sphere --precision wide -o sphere-wide.lht");
  cmd->add_option("--scene", args->scene, "Scene file whose [[lattices]] entry to rasterize")->check(CLI::ExistingFile);
  cmd->add_option("--name", args->name, "Name of the [[lattices]] entry (with --scene)");
  cmd->add_option("--shape", args->shape, "sphere (centred) or capsule (axis along z from 0 to --length)");
  cmd->add_option("--radius", args->radius, "Radius in lambda (default 0.5)");
  cmd->add_option("--length", args->length, "Capsule axis length in lambda, caps excluded (default 10)");
  auto* oversample = cmd->add_option("--oversample", args->oversample,
                                     "Lattice oversampling f_lat >= 1 (default 1, or the scene's)");
  cmd->add_option("-o,--output", args->output, "The .lht file to write (atomically)")->required();
  cmd->add_option("--precision", args->precision,
                  fmt::format("LHT entry precision: {} (default: the scene's `precision`, else thesis)",
                              lhtPrecisionChoices()));
  cmd->add_flag("--stats", args->stats, "Print one line: pairs= hits= entries= bytes= precision= build_ms=");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)");
  cmd->callback([args, oversample] {
    args->oversampleGiven = oversample->count() > 0;
    runRasterize(*args);
  });
}

// Every command that loads scenes (render, rasterize) must know the lattice
// section and node types; this file is always linked into the executable.
const bool latticeSceneTypesRegistered = [] {
  registerLatticeSceneTypes();
  return true;
}();

}  // namespace lattice::app
