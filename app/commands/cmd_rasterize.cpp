// `lattice rasterize`: builds a lattice hash table (thesis sec. 2.1) for a
// shape or for a [[lattices]] entry of a scene and writes it as a .lht file.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <optional>

#include "app/commands/commands.hpp"
#include "app/cli/number_flags.hpp"
#include "foundation/error.hpp"
#include "loader/table_build.hpp"

namespace {

using namespace lattice;
using namespace lattice::lht;

struct RasterizeArgs {
  std::string scene, name, shape, output;
  double radius = 0.5, length = 10.0, oversample = 1.0;
  bool stats = false;
  std::string precision;  // empty: the scene's, or the thesis's for --shape
  std::string form;       // empty: the scene's `form`, or hashed for --shape
  unsigned threads = 0;
};

void runRasterize(const RasterizeArgs& args, bool oversampleGiven) {
  TableRequest request{args.scene, args.name, args.shape, args.radius, args.length, std::nullopt, {}};
  if (oversampleGiven) request.oversample = args.oversample;  // --oversample overrides the scene
  if (!args.precision.empty()) request.settings.precision = parseLhtPrecision(args.precision, "--precision");
  if (!args.form.empty()) request.settings.form = parseLhtForm(args.form, "--form");
  request.settings.threads = args.threads;
  const BuiltTable built = buildLatticeTable(request);
  writeLhtFile(args.output, built.lht);
  if (args.stats)
    fmt::print("pairs={} hits={} entries={} bytes={} precision={} build_ms={:.0f} form={}\n", built.lht.pairs,
               built.lht.hits, built.lht.entryCount(), built.lht.tableBytes(), lhtPrecisionName(built.lht.precision()),
               built.stats.buildMs, lhtFormName(built.lht.form()));
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
      "  lattice rasterize --shape sphere --precision wide -o sphere-wide.lht\n"
      "  lattice rasterize --shape capsule --length 100 --form compressed -o line.lht");
  cmd->add_option("--scene", args->scene, "Scene file whose [[lattices]] entry to rasterize")->check(CLI::ExistingFile);
  cmd->add_option("--name", args->name, "Name of the [[lattices]] entry (with --scene)");
  cmd->add_option("--shape", args->shape, "sphere (centred) or capsule (axis along z from 0 to --length)");
  // A lattice spans at most 255 cells a side (thesis 2.3: one byte a coordinate).
  cmd->add_option("--radius", args->radius, "Radius in lambda (default 0.5)")->check(lattice::app::numberIn({1e-3, 127}));
  cmd->add_option("--length", args->length, "Capsule axis length in lambda, caps excluded (default 10)")
      ->check(lattice::app::numberIn({0, 253}));
  auto* oversample = cmd->add_option("--oversample", args->oversample,
                                     "Lattice oversampling f_lat >= 1 (default 1, or the scene's)")
                        ->check(lattice::app::numberIn({1, 255}));
  cmd->add_option("-o,--output", args->output, "The .lht file to write (atomically)")->required();
  cmd->add_option("--precision", args->precision,
                  fmt::format("LHT entry precision: {} (default: the scene's `precision`, else thesis)",
                              lhtPrecisionChoices()));
  cmd->add_option("--form", args->form,
                  fmt::format("LHT form: {} (default: the scene's `form`, else hashed; docs/lattices.md, \"The "
                              "compressed LHT\")",
                              lhtFormChoices()));
  cmd->add_flag("--stats", args->stats,
                "Print one line: pairs= hits= entries= bytes= precision= build_ms= form= (bytes: the table in memory)");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
      ->check(lattice::app::numberIn({1, 256, true}));
  cmd->callback([args, oversample] { runRasterize(*args, oversample->count() > 0); });
}

}  // namespace lattice::app
