#include "lht/table/on_demand_table.hpp"

namespace lattice::lht {

OnDemandTable::OnDemandTable(const LatticeBox& box, std::shared_ptr<const Primitive<double>> object,
                             LhtPrecision precision, std::uint64_t capacityBytes)
    : box_(box), object_(std::move(object)), tracer_(box_, *object_), index_(box.cells()), precision_(precision),
      capacity_(capacityBytes / kStoredBytes) {
  const std::uint64_t pairs = std::uint64_t(index_.count()) * index_.count();
  if (pairs <= kMaxMissBits) missBits_ = std::vector<std::atomic<std::uint64_t>>((pairs + 63) / 64);
}

const std::uint8_t* OnDemandTable::findPayload(const LatticePoint& in, const LatticePoint& out) const {
  const std::uint64_t i = index_.indexOf(in), o = index_.indexOf(out);
  if (i == BoundaryIndex::kNotOnBoundary || o == BoundaryIndex::kNotOnBoundary || i == o) return nullptr;
  const std::uint64_t key = i * index_.count() + o;
  const std::uint64_t missBit = std::uint64_t(1) << (key % 64);
  if (!missBits_.empty() && (missBits_[key / 64].load(std::memory_order_relaxed) & missBit)) return nullptr;
  Shard& shard = shards_[(key * 0x9E3779B97F4A7C15ull) >> 58];  // the top 6 bits: 64 shards
  {
    std::lock_guard lock(shard.mutex);
    const auto found = shard.answers.find(key);
    if (found != shard.answers.end()) return found->second.hit ? found->second.payload.data() : nullptr;
  }
  // Traced outside the lock: other threads keep looking up meanwhile.
  RasterHit hit;
  Answer answer;
  answer.hit = tracer_.trace(in, out, hit);
  traced_.add();
  if (answer.hit) encodePayload(hit, precision_, answer.payload.data());
  if (!answer.hit && !missBits_.empty()) {
    // Two threads may both set it; only the first counts it.
    if (!(missBits_[key / 64].fetch_or(missBit, std::memory_order_relaxed) & missBit))
      missesStored_.add();
    return nullptr;
  }
  std::lock_guard lock(shard.mutex);
  const auto found = shard.answers.find(key);
  if (found != shard.answers.end()) return found->second.hit ? found->second.payload.data() : nullptr;
  if (mapAnswers_.value() >= capacity_) {
    refused_.add();
    if (!answer.hit) return nullptr;
    // Not stored: the caller decodes it at once, before this thread asks again.
    LATTICE_THREAD_LOCAL std::array<std::uint8_t, 6> unstored;
    unstored = answer.payload;
    return unstored.data();
  }
  (answer.hit ? hitsStored_ : missesStored_).add();
  mapAnswers_.add();
  const auto stored = shard.answers.emplace(key, answer).first;
  return stored->second.hit ? stored->second.payload.data() : nullptr;
}

OnDemandCounts OnDemandTable::counts() const {
  return {hitsStored_.value(), missesStored_.value(), traced_.value(),          refused_.value(),
          capacity_ * kStoredBytes, mapAnswers_.value(), missBits_.size() * 8};
}

}  // namespace lattice::lht
