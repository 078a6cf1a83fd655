#pragma once
// A [[lattices]] entry of a scene file (docs/lattices.md) and the settings a
// lattice's table is built with.
//
// Method: a definition is what the file says, fixed once loaded; how its
// table is built this run (an entry form forced from the command line, the
// rasterizer's threads, a memory budget's packing) is a TableSettings value
// handed in when the scene is loaded or its tables rebound
// (loader/lattice_scene_loader.hpp), never written into the definition.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>  // std::call_once: libstdc++ has it in the single thread model too
#include <optional>
#include <string>

#include "lht/leaf/lookup_mode.hpp"
#include "lht/table/lht_form.hpp"
#include "lht/table/lht_precision.hpp"
#include "render/scene/scene.hpp"

namespace lattice::lht {

class LatticeDefinition;
class LookupStatsBook;
class LazyRasterEstimate;  // lht/raster/raster_estimate.hpp

// 64 MiB: Plate 7 at f_lat 4 stores 1.3 million answers (62 MiB at 48 bytes).
inline constexpr std::uint64_t kDefaultOnDemandCacheBytes = std::uint64_t(64) << 20;

// Under a memory budget: the entry form to pack a freshly rasterized table
// in, given the form asked for, its entry count and the bytes its hit list
// holds meanwhile. A table packed in another form than asked is not written
// to the lattice's cache.
using TablePackingHook = std::function<LhtPrecision(const LatticeDefinition& lattice, LhtPrecision requested,
                                                    std::uint64_t entries, std::uint64_t hitListBytes)>;

// Under a memory budget: asked before a lattice is rasterized, with the
// estimate of what rasterizing it holds (its worst case at once, the sampled
// one traced when asked for), the table form and the entry form asked for. Throws lattice::Error to refuse it; else returns the most hits
// the rasterizer may hold (its running count), and what to say if it passes
// them.
struct RasterAllowance {
  std::uint64_t maxHits = UINT64_MAX;
  std::string refusal;  // follows "rasterizing stopped at N hits (...), "
};
using RasterAdmissionHook = std::function<RasterAllowance(const LatticeDefinition& lattice, LazyRasterEstimate& estimate,
                                                          LhtForm form, LhtPrecision requested)>;

struct TableSettings {
  std::optional<LhtPrecision> precision;  // every table's entry form; unset: each definition's own
  unsigned threads = 0;                   // the set-up's threads (rasterizing, a scatter's placements); 0: all cores
  bool progress = true;                   // a progress bar while rasterizing (on a terminal)
  TablePackingHook packing;               // unset: tables are packed as asked
  RasterAdmissionHook admission;          // unset: every lattice is rasterized, without a count
  std::optional<LhtForm> form;            // every table's form; unset: each definition's own
  // The on-demand form's bound on stored answers (`--lht-cache SIZE`).
  std::uint64_t onDemandCacheBytes = kDefaultOnDemandCacheBytes;
  // Set: every lattice leaf counts its look-ups here (`render --lht-stats`,
  // lht/leaf/lookup_stats.hpp); unset, the leaves count nothing.
  std::shared_ptr<LookupStatsBook> stats;
  // Every leaf's look-up (`--lattice-lookup`); unset: each definition's own.
  // Not part of the table: the same cache serves both.
  std::optional<LatticeLookup> lookup;
};

class LatticeDefinition {
 public:
  std::string name;
  double lambda = 1.0;
  double oversample = 1.0;
  NodeDesc object;
  std::string objectText;  // canonical text of the object table (loader/canonical_toml.hpp)
  std::optional<std::filesystem::path> cache;
  bool shadows = true;  // false: this lattice casts no shadows (thesis plate 3)
  LhtPrecision precision = LhtPrecision::Thesis;  // the entry form the file asks for
  LhtForm form = LhtForm::Hashed;                 // the table form the file asks for (`form`)
  LatticeLookup lookup = LatticeLookup::Thesis;   // how its leaves read the table (`lookup`)
  std::string origin;                             // "scene.toml:12:1"

  // The entry form its table is built in under `settings`.
  LhtPrecision precisionUnder(const TableSettings& settings) const { return settings.precision.value_or(precision); }
  // The table form under `settings`.
  LhtForm formUnder(const TableSettings& settings) const { return settings.form.value_or(form); }
  // The leaves' look-up under `settings`.
  LatticeLookup lookupUnder(const TableSettings& settings) const { return settings.lookup.value_or(lookup); }
  // Hash of everything that decides the table's contents (the entry form
  // included, so a cache of another form is stale).
  std::uint64_t hashFor(LhtPrecision entryForm) const;
  std::uint64_t hash() const { return hashFor(precision); }  // in the form the file asks for
  // The object's box in its own coordinates (computed once, shared by copies).
  const Bounds<double>& objectBounds() const;

 private:
  struct BoundsCache {
    std::once_flag once;
    Bounds<double> bounds;
  };
  std::shared_ptr<BoundsCache> bounds_ = std::make_shared<BoundsCache>();
};

using LatticeDefinitionPtr = std::shared_ptr<const LatticeDefinition>;

}  // namespace lattice::lht
