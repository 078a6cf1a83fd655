#include "loader/lattice_tables.hpp"

#include "lht/raster/lattice_object.hpp"
#include "loader/table_build.hpp"

namespace lattice::lht {

namespace {

// An empty table over the lattice's box, tracing the object as it is asked.
std::shared_ptr<const LhtFile> onDemandTable(const LatticeDefinition& lattice, LhtPrecision precision,
                                             std::uint64_t capacityBytes) {
  const LatticeObject object = sceneObject(lattice.object, lattice.objectText);
  auto lht = std::make_shared<LhtFile>();
  lht->box = LatticeBox(object.bounds, lattice.lambda, lattice.oversample);
  lht->objectHash = lattice.hashFor(precision);
  lht->table = std::make_shared<const OnDemandTable>(lht->box, object.primitive, precision, capacityBytes);
  return lht;
}

}  // namespace

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
    if (lattice->formUnder(settings_) == LhtForm::OnDemand) {
      slot->table = onDemandTable(*lattice, form, settings_.onDemandCacheBytes);  // no cache: nothing to keep
    } else if (cache && std::filesystem::exists(*cache)) {
      slot->table =
          std::make_shared<const LhtFile>(readLhtFile(*cache, lattice->hashFor(form), form, lattice->formUnder(settings_)));
    } else {
      auto built = std::make_shared<const LhtFile>(buildLatticeTable(*lattice, settings_).lht);
      if (cache && built->precision() == form) writeLhtFile(*cache, *built, AtomicFile::Landing::Now);
      slot->table = std::move(built);
    }
    if (settings_.stats) slot->stats = settings_.stats->add(lattice->name, slot->table);
  });
  return slot;
}

}  // namespace lattice::lht
