// `lattice lht-info FILE`: what a .lht file holds - its lattice, the object
// hash, the thesis's N_lp / N_iz, and how well the hash table is packed.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands/commands.hpp"
#include "lht/grid/boundary_index.hpp"
#include "lht/file/lht_file.hpp"

namespace {

void runLhtInfo(const std::string& path) {
  using namespace lattice::lht;
  const LhtFile lht = readLhtFile(path);
  const auto& c = lht.box.cells();
  fmt::print("file:          {}\n", path);
  const LhtPrecisionInfo& precision = lhtPrecisionInfo(lht.precision());
  fmt::print("format:        version {}\n", lht.version);
  fmt::print("form:          {}\n", std::visit(
                                          [](const auto& t) { return std::decay_t<decltype(formTable(t))>::kFormSummary; },
                                          lht.table));
  fmt::print("precision:     {} ({}-byte entries: {})\n", precision.name, precision.entryBytes, precision.summary);
  fmt::print("lattice:       {} x {} x {} cells, lambda {:g}, f_lat {:g} (cell {:g})\n", c[0], c[1], c[2],
             lht.box.lambda(), lht.box.oversample(), lht.box.cellSize());
  fmt::print("origin:        ({:g}, {:g}, {:g}) in object coordinates\n", lht.box.origin().x, lht.box.origin().y,
             lht.box.origin().z);
  fmt::print("object hash:   {:016x}\n", lht.objectHash);
  fmt::print("pairs (N_lp):  {}\n", lht.pairs);
  fmt::print("hits (N_iz):   {}\n", lht.hits);
  fmt::print("entries:       {} distinct (p_i, p_o)\n", lht.entryCount());
  // What a render can reference at most (`render --lht-stats` counts what it does).
  const std::uint64_t points = BoundaryIndex(c).count();
  const std::uint64_t space = points * (points - 1);
  fmt::print("pair space:    {} boundary points, {} ordered pairs; entries fill {:.2f} % of it\n", points, space,
             space ? 100.0 * double(lht.entryCount()) / double(space) : 0.0);
  std::visit(
      [&](const auto& t) {
        if constexpr (requires { formTable(t).describe(lht.hits); })
          for (const std::string& line : formTable(t).describe(lht.hits)) fmt::print("{}\n", line);
      },
      lht.table);
}

}  // namespace

namespace lattice::app {

void addLhtInfo(CLI::App& root) {
  auto* cmd = root.add_subcommand("lht-info",
                                  "Print the header and statistics of a .lht lattice hash table file: lattice size,\n"
                                  "spacing, object hash, N_lp / N_iz, form and entry precision, entries, the pair\n"
                                  "space they fill, bytes per entry, and (hashed) load factor and probe\n"
                                  "lengths or (compressed) bitmap and payload bytes. The checksum is verified.");
  auto path = std::make_shared<std::string>();
  cmd->add_option("file", *path, "The .lht file")->required();
  cmd->callback([=] { runLhtInfo(*path); });
}

}  // namespace lattice::app
