#include "lht/leaf/lookup_stats.hpp"

#include <fmt/format.h>

#include <bit>

#include "lht/leaf/table_lookup.hpp"

namespace lattice::lht {

LookupStats::LookupStats(std::string lattice, std::shared_ptr<const LhtFile> lht)
    : lattice_(std::move(lattice)), lht_(std::move(lht)), index_(lht_->box.cells()) {
  const std::uint64_t bits = std::uint64_t(index_.count()) * index_.count();
  if (bits <= kMaxPairBits) asked_ = std::vector<std::atomic<std::uint64_t>>((bits + 63) / 64);
}

LookupSummary LookupStats::summary() const {
  LookupSummary s;
  s.lattice = lattice_;
  s.lookups = lookups_.value();
  s.hits = hits_.value();
  s.misses = s.lookups - s.hits;
  s.offSurface = offSurface_.value();
  const std::uint64_t p = index_.count();
  s.pairSpace = p * (p - 1);
  s.entries = lht_->entryCount();
  s.nIz = lht_->hits;
  s.oversample = lht_->box.oversample();
  s.distinctCounted = !asked_.empty();
  // Before the walk below, whose look-ups an on-demand table would answer too.
  if (lht_->form() == LhtForm::OnDemand) s.onDemand = lht_->onDemand().counts();
  const LhtLookup lookup(*lht_);
  for (std::size_t w = 0; w < asked_.size(); ++w) {
    for (std::uint64_t word = asked_[w].load(std::memory_order_relaxed); word; word &= word - 1) {
      const std::uint64_t bit = w * 64 + static_cast<std::uint64_t>(std::countr_zero(word));
      ++s.distinctPairs;
      if (s.onDemand) continue;  // its counts say what it built; asking would trace refused pairs again
      const LatticePoint in = index_.pointAt(static_cast<std::uint32_t>(bit / p));
      const LatticePoint out = index_.pointAt(static_cast<std::uint32_t>(bit % p));
      if (!lookup.payload(in, out)) continue;
      ++s.entriesReferenced;
      s.nIzReferenced += static_cast<std::uint64_t>(
          LatticeBox::pairMultiplicity(lht_->box.facesOf(in), lht_->box.facesOf(out)));
    }
  }
  return s;
}

LookupStats* LookupStatsBook::add(std::string lattice, std::shared_ptr<const LhtFile> lht) {
  auto stats = std::make_unique<LookupStats>(std::move(lattice), std::move(lht));
  std::lock_guard lock(mutex_);
  stats_.push_back(std::move(stats));
  return stats_.back().get();
}

std::vector<LookupSummary> LookupStatsBook::summaries() const {
  std::lock_guard lock(mutex_);
  std::vector<LookupSummary> out;
  for (const auto& stats : stats_) out.push_back(stats->summary());
  return out;
}

std::string describeLookups(const LookupSummary& s) {
  const auto percent = [](std::uint64_t part, std::uint64_t whole) { return whole ? 100.0 * double(part) / double(whole) : 0.0; };
  std::string out = fmt::format("lattice '{}' (f_lat {:g}): {} look-ups, {} hits, {} misses", s.lattice, s.oversample,
                                s.lookups, s.hits, s.misses);
  if (s.offSurface) out += fmt::format(" ({} with a point off the box's surface)", s.offSurface);
  if (!s.distinctCounted) return out + "; distinct pairs not counted (pair space above 2^33 bits)";
  out += fmt::format("\n  distinct (p_i, p_o) asked: {} ({:.3f} % of the {} ordered pairs)", s.distinctPairs,
                     percent(s.distinctPairs, s.pairSpace), s.pairSpace);
  if (s.onDemand) {
    const OnDemandCounts& d = *s.onDemand;
    out += fmt::format("\n  built on demand: {} hits and {} misses stored ({} bytes of the {}-byte cache, and a "
                       "{}-byte miss bitmap), {} pairs traced, {} stores refused (cache full)",
                       d.hitsStored, d.missesStored, d.mapAnswers * OnDemandTable::kStoredBytes, d.capacityBytes,
                       d.missBitmapBytes, d.traced, d.refused);
    return out;
  }
  out += fmt::format("\n  entries referenced: {} of {} ({:.2f} %); {:.2f} % of N_iz = {} counted as eq. 1.3 does",
                     s.entriesReferenced, s.entries, percent(s.entriesReferenced, s.entries),
                     percent(s.nIzReferenced, s.nIz), s.nIz);
  out += fmt::format("\n  look-ups per entry: {:.2f}; hits per referenced entry: {:.2f}",
                     s.entries ? double(s.lookups) / double(s.entries) : 0.0,
                     s.entriesReferenced ? double(s.hits) / double(s.entriesReferenced) : 0.0);
  return out;
}

}  // namespace lattice::lht
