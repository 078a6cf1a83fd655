// `lattice lht-info FILE`: what a .lht file holds - its lattice, the object
// hash, the thesis's N_lp / N_iz, and how well the hash table is packed.
#include <fmt/format.h>

#include "app/commands.hpp"
#include "lht/grid/boundary_index.hpp"
#include "lht/file/lht_file.hpp"

namespace {

void printHashed(const lattice::lht::LatticeHashTable& t) {
  using namespace lattice::lht;
  fmt::print("layout:        open addressing, linear probing, {} slots\n", t.capacity());
  fmt::print("load factor:   {:.3f} of the slots used\n", t.loadFactor());
  fmt::print("table bytes:   {} ({:.2f} bytes/entry, {} bytes per slot)\n", t.bytes(), t.bytesPerEntry(),
             t.entryStride());
  const ProbeStats probes = t.probeStats();
  fmt::print("probes:        a hit reads {:.2f} slots on average, a miss {:.2f}; longest displacement {}\n",
             probes.meanHitSlots, probes.meanMissSlots, probes.longestProbe);
  for (std::size_t k = 0; k < probes.displacementHistogram.size(); ++k)
    if (probes.displacementHistogram[k])
      fmt::print("  {:>3} past home: {} entries\n", k, probes.displacementHistogram[k]);
}

void printCompressed(const lattice::lht::CompressedTable& t, std::uint64_t nIz) {
  using namespace lattice::lht;
  fmt::print("pair layout:   {} ({} bits)\n",
             t.layout() == PairLayout::Symmetric ? "symmetric, one bit per unordered pair, two payloads a bit"
                                                 : "ordered, one bit per ordered pair",
             t.bitCount());
  fmt::print("table bytes:   {} ({:.2f} bytes/entry, {:.2f} per N_iz): bitmap {}, rank directory {}, payloads {} "
             "({} bytes each)\n",
             t.bytes(), t.bytesPerEntry(), nIz ? double(t.bytes()) / double(nIz) : 0.0, t.bitmapBytes(), t.rankBytes(),
             t.payloads().size(), payloadBytes(t.precision()));
}

void runLhtInfo(const std::string& path) {
  using namespace lattice::lht;
  const LhtFile lht = readLhtFile(path);
  const auto& c = lht.box.cells();
  fmt::print("file:          {}\n", path);
  const LhtPrecisionInfo& precision = lhtPrecisionInfo(lht.precision());
  fmt::print("format:        version {}\n", lht.version);
  fmt::print("form:          {}\n", lht.form() == LhtForm::Compressed
                                        ? "compressed (no key, no chain: a rank bitmap over the pair space)"
                                        : lht.version < kLhtVersion
                                              ? "hashed (read from the chained layout, thesis sec. 2.3; held open-addressed)"
                                              : "hashed (open-addressed: key, payload)");
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
  if (lht.form() == LhtForm::Compressed)
    printCompressed(lht.compressed(), lht.hits);
  else
    printHashed(lht.hashed());
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
