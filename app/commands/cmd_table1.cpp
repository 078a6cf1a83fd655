// `lattice table1`: recomputes the thesis's Table 1 (N_lp pairs tried, N_iz
// intersections found) and prints it beside the published numbers.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands/commands.hpp"
#include "app/cli/number_flags.hpp"
#include "lht/raster/thesis_table1.hpp"

namespace {

void runTable1(bool quick, unsigned threads) {
  using namespace lattice::lht;
  fmt::print("{:<26} {:>5} {:>9} {:>10} {:>10} {:>10} {:>10}  {}\n", "object (units of lambda)", "f_lat", "cells",
             "N_lp", "thesis", "N_iz", "thesis", "");
  for (const Table1Row& row : table1Rows()) {
    if (quick && row.thesisPairs > 1000000) continue;
    RasterOptions options;
    options.threads = threads;
    options.progress = true;
    const Table1Result r = computeTable1Row(row, options);
    std::string verdict;
    if (row.comparable)
      verdict = r.stats.pairs == row.thesisPairs && r.stats.hits == row.thesisHits ? "exact" : "DIFFERS";
    else
      verdict = fmt::format("not comparable: ours is {}", row.geometry);
    fmt::print("{:<26} {:>5g} {:>9} {:>10} {:>10} {:>10} {:>10}  {}\n", row.object, row.oversample,
               fmt::format("{}x{}x{}", r.cells[0], r.cells[1], r.cells[2]), r.stats.pairs, row.thesisPairs,
               r.stats.hits, row.thesisHits, verdict);
    std::fflush(stdout);
  }
}

}  // namespace

namespace lattice::app {

void addTable1(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "table1",
      "Recompute thesis Table 1: pairs (p_i, p_o) tried (N_lp, eq. 1.3) and intersections found (N_iz)\n"
      "for each object and oversampling f_lat, beside the published numbers. The sphere and straight\n"
      "lines must match exactly; the spiral, hook and hair geometry is ours (see docs/lattices.md).");
  auto quick = std::make_shared<bool>(false);
  auto threads = std::make_shared<unsigned>(0);
  cmd->add_flag("--quick", *quick, "Skip the rows with more than a million pairs");
  cmd->add_option("--threads", *threads, "Worker threads (default: all cores)")
      ->check(lattice::app::numberIn({1, 256, true}));
  cmd->callback([=] { runTable1(*quick, *threads); });
}

}  // namespace lattice::app
