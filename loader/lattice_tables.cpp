#include "loader/lattice_tables.hpp"

#include <fmt/core.h>

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

// A cache an older Lattice wrote in a layout this one no longer reads is
// rebuilt (and rewritten) as if it were missing, with a one-line note.
bool retiredCache(const std::filesystem::path& cache) {
  const std::optional<std::uint32_t> version = retiredLhtVersion(cache);
  if (version)
    fmt::print(stderr, "lattice: note: {}: an old .lht cache (version {}); rebuilding it\n", cache.string(), *version);
  return version.has_value();
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
    } else if (cache && std::filesystem::exists(*cache) && !retiredCache(*cache)) {
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
