#pragma once
// The tables of one loaded scene's lattices, built under one TableSettings.
//
// Method: each lattice's table is made once, the first time a leaf of it is
// built: read from the lattice's cache when that file matches (same object,
// spacing, oversampling and entry form), else rasterized
// (loader/table_build.hpp) and written to the cache if one is named and the
// table is in the form asked for. Every instance of a lattice shares it.
// Thread-safe.
#include <map>
#include <memory>
#include <mutex>

#include "foundation/threads.hpp"

#include "loader/lattice_definition.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/leaf/lookup_stats.hpp"

namespace lattice::lht {

class LatticeTables {
 public:
  explicit LatticeTables(TableSettings settings) : settings_(std::move(settings)) {}
  LatticeTables(const LatticeTables&) = delete;
  LatticeTables& operator=(const LatticeTables&) = delete;

  const TableSettings& settings() const { return settings_; }
  std::shared_ptr<const LhtFile> table(const LatticeDefinitionPtr& lattice) const;
  // Where the lattice's leaves count their look-ups: null unless the
  // settings ask for statistics (builds the table first).
  LookupStats* lookupStats(const LatticeDefinitionPtr& lattice) const;

 private:
  struct Slot {
    LatticeDefinitionPtr lattice;  // keeps the key's address from being reused
    std::once_flag once;
    std::shared_ptr<const LhtFile> table;
    LookupStats* stats = nullptr;  // owned by settings_.stats
  };
  std::shared_ptr<Slot> slotOf(const LatticeDefinitionPtr& lattice) const;
  const TableSettings settings_;
  mutable Mutex mutex_;  // guards slots_ (not the building, which each slot's once_flag orders)
  mutable std::map<const LatticeDefinition*, std::shared_ptr<Slot>> slots_;
};

}  // namespace lattice::lht
