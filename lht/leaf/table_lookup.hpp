#pragma once
// One look-up over a lattice's table in whichever form it was built or read
// (lht/table/table_forms.hpp): the payload of (p_i, p_o), or null.
//
// Method: a chain of comparisons of the form's code, one per form of the
// list, rather than a virtual call or std::visit's jump table; the chain goes
// the same way for every look-up of a render, so it is predicted, and a new
// form joins it through the list without an edit here.
#include <utility>

#include "lht/file/lht_file.hpp"

namespace lattice::lht {

class LhtLookup {
 public:
  explicit LhtLookup(const LhtFile& lht)
      : table_(std::visit([](const auto& t) -> const void* { return &formTable(t); }, lht.table)),
        form_(lht.table.index()), precision_(lht.precision()) {}

  const std::uint8_t* payload(const LatticePoint& in, const LatticePoint& out) const {
    return payloadIn(in, out, std::make_index_sequence<kLhtFormCount>{});
  }
  std::optional<LhtHit> find(const LatticePoint& in, const LatticePoint& out) const {
    const std::uint8_t* p = payload(in, out);
    if (!p) return std::nullopt;
    return toHit(decodePayloadIntegers(p, precision_));
  }
  LhtPrecision precision() const { return precision_; }

 private:
  template <std::size_t... I>
  const std::uint8_t* payloadIn(const LatticePoint& in, const LatticePoint& out, std::index_sequence<I...>) const {
    const std::uint8_t* found = nullptr;
    (void)((form_ == I ? (found = static_cast<const FormAt<I>*>(table_)->findPayload(in, out), true) : false) || ...);
    return found;
  }

  const void* table_;  // the form's table object, FormAt<form_>
  std::size_t form_;
  LhtPrecision precision_;
};

}  // namespace lattice::lht
