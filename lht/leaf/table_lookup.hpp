#pragma once
// One look-up over a lattice's table in whichever form it was built or read
// (lht/table/lht_form.hpp): the payload of (p_i, p_o), or null.
//
// Method: a branch on the form per look-up rather than a virtual call; the
// branch goes the same way for every look-up of a render, so it is predicted.
#include "lht/file/lht_file.hpp"

namespace lattice::lht {

class LhtLookup {
 public:
  explicit LhtLookup(const LhtFile& lht)
      : hashed_(std::get_if<LatticeHashTable>(&lht.table)), compressed_(std::get_if<CompressedTable>(&lht.table)),
        onDemand_(lht.form() == LhtForm::OnDemand ? &lht.onDemand() : nullptr), precision_(lht.precision()) {}

  const std::uint8_t* payload(const LatticePoint& in, const LatticePoint& out) const {
    if (compressed_) return compressed_->findPayload(in, out);
    if (onDemand_) return onDemand_->findPayload(in, out);
    return hashed_->findPayload(in, out);
  }
  std::optional<LhtHit> find(const LatticePoint& in, const LatticePoint& out) const {
    const std::uint8_t* p = payload(in, out);
    if (!p) return std::nullopt;
    return toHit(decodePayloadIntegers(p, precision_));
  }
  LhtPrecision precision() const { return precision_; }

 private:
  const LatticeHashTable* hashed_;
  const CompressedTable* compressed_;
  const OnDemandTable* onDemand_;
  LhtPrecision precision_;
};

}  // namespace lattice::lht
