// `lattice lht-info FILE`: what a .lht file holds - its lattice, the object
// hash, the thesis's N_lp / N_iz, and how well the hash table is packed.
#include <fmt/format.h>

#include "app/commands.hpp"
#include "lht/lht_file.hpp"

namespace {

void runLhtInfo(const std::string& path) {
  using namespace lattice::lht;
  const LhtFile lht = readLhtFile(path);
  const auto& c = lht.box.cells();
  const auto& t = lht.table;
  fmt::print("file:          {}\n", path);
  const LhtPrecisionInfo& precision = lhtPrecisionInfo(t.precision());
  fmt::print("format:        version {}\n", lht.version);
  fmt::print("precision:     {} ({}-byte entries: {})\n", precision.name, precision.entryBytes, precision.summary);
  fmt::print("lattice:       {} x {} x {} cells, lambda {:g}, f_lat {:g} (cell {:g})\n", c[0], c[1], c[2],
             lht.box.lambda(), lht.box.oversample(), lht.box.cellSize());
  fmt::print("origin:        ({:g}, {:g}, {:g}) in object coordinates\n", lht.box.origin().x, lht.box.origin().y,
             lht.box.origin().z);
  fmt::print("object hash:   {:016x}\n", lht.objectHash);
  fmt::print("pairs (N_lp):  {}\n", lht.pairs);
  fmt::print("hits (N_iz):   {}\n", lht.hits);
  fmt::print("entries:       {} distinct (p_i, p_o)\n", t.entryCount());
  fmt::print("buckets:       {} primary + {} overflow slots\n", t.bucketCount(), t.overflowCount());
  fmt::print("load factor:   {:.3f} entries per bucket\n", t.loadFactor());
  fmt::print("table bytes:   {} ({:.2f} bytes/entry, {} bytes per slot)\n", t.bytes(), t.bytesPerEntry(),
             t.entryStride());
  const ChainStats chains = t.chainStats();
  fmt::print("chains:        {} buckets used, longest {}\n", chains.usedBuckets, chains.longestChain);
  for (std::size_t k = 0; k < chains.chainLengthHistogram.size(); ++k)
    fmt::print("  length {:>3}: {} buckets\n", k, chains.chainLengthHistogram[k]);
}

}  // namespace

namespace lattice::app {

void addLhtInfo(CLI::App& root) {
  auto* cmd = root.add_subcommand("lht-info",
                                  "Print the header and statistics of a .lht lattice hash table file: lattice size,\n"
                                  "spacing, object hash, N_lp / N_iz, entry precision, entries, load factor, bytes\n"
                                  "per entry and overflow chain lengths. The file's checksum is verified.");
  auto path = std::make_shared<std::string>();
  cmd->add_option("file", *path, "The .lht file")->required();
  cmd->callback([=] { runLhtInfo(*path); });
}

}  // namespace lattice::app
