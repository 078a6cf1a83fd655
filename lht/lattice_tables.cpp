#include "lht/lattice_tables.hpp"

#include "lht/table_build.hpp"

namespace lattice::lht {

std::shared_ptr<const LhtFile> LatticeTables::table(const LatticeDefinitionPtr& lattice) const {
  return slotOf(lattice)->table;
}

LookupStats* LatticeTables::lookupStats(const LatticeDefinitionPtr& lattice) const { return slotOf(lattice)->stats; }

std::shared_ptr<LatticeTables::Slot> LatticeTables::slotOf(const LatticeDefinitionPtr& lattice) const {
  std::shared_ptr<Slot> slot;
  {
    std::lock_guard lock(mutex_);
    std::shared_ptr<Slot>& entry = slots_[lattice.get()];
    if (!entry) {
      entry = std::make_shared<Slot>();
      entry->lattice = lattice;
    }
    slot = entry;
  }
  std::call_once(slot->once, [&] {
    const LhtPrecision form = lattice->precisionUnder(settings_);
    const auto& cache = lattice->cache;
    if (cache && std::filesystem::exists(*cache)) {
      slot->table =
          std::make_shared<const LhtFile>(readLhtFile(*cache, lattice->hashFor(form), form, lattice->formUnder(settings_)));
    } else {
      auto built = std::make_shared<const LhtFile>(buildLatticeTable(*lattice, settings_).lht);
      if (cache && built->precision() == form) writeLhtFile(*cache, *built);
      slot->table = std::move(built);
    }
    if (settings_.stats) slot->stats = settings_.stats->add(lattice->name, slot->table);
  });
  return slot;
}

}  // namespace lattice::lht
