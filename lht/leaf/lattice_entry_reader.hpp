#pragma once
// How a lattice leaf (lht/leaf/lattice_leaf.cpp) reads a table entry in its
// arithmetic T: the fraction s along the segment and the world normal.
//
// Method: this generic version serves the IEEE types: the table's decoded
// hit (s and a unit normal in double, LhtLookup::find) converted to T,
// the normal carried to the world by the inverse transpose of
// lattice -> world. An arithmetic that must not go through double
// specialises EntryReader in its own file, as fixed point does
// (lht/leaf/lattice_entry_reader_fixed.hpp); the leaf has no per-type branch.
//
// A read is split in two so that callers pay only for what they use: find()
// gives the entry (its payload), s() its fraction alone, normal() the world
// normal. Shadow rays and a chord's far end often need s and never the
// normal; read() is the three together.
#include <cstdint>

#include "lht/table/entry_codec.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "foundation/vec.hpp"

namespace lattice::lht {

template <typename T>
class EntryReader {
 public:
  // Throws lattice::Error(Input) when T cannot follow the lattice placed by
  // latticeToWorld (the generic arithmetics always can). worldToLattice is
  // glm::inverse(latticeToWorld), which the leaf has already taken.
  EntryReader(const LhtLookup& table, const Mat4d& /*latticeToWorld*/, const Mat4d& worldToLattice)
      : table_(table), normalToWorld_(glm::transpose(Mat3<double>(worldToLattice))) {}
  // With the map normalMap() of a reader built as above (a baked placement).
  EntryReader(const LhtLookup& table, const Mat3<T>& normalMap) : table_(table), normalToWorld_(normalMap) {}
  const Mat3<T>& normalMap() const { return normalToWorld_; }

  // The entry of (from, to), or null.
  const std::uint8_t* find(const LatticePoint& from, const LatticePoint& to) const { return table_.payload(from, to); }
  // The same s and normal as LhtLookup::find() gives, converted to T.
  T s(const std::uint8_t* entry) const {
    const EntryFraction f = decodePayloadFraction(entry, table_.precision());
    return T(f.numerator / double(f.denominator));
  }
  Vec3<T> normal(const std::uint8_t* entry) const {
    const LhtHit hit = toHit(decodePayloadIntegers(entry, table_.precision()));
    return lattice::normalize(normalToWorld_ * Vec3<T>(hit.normal));
  }

  // The entry of (from, to): false when there is none.
  bool read(const LatticePoint& from, const LatticePoint& to, T& sOut, Vec3<T>& worldNormal) const {
    const std::uint8_t* entry = find(from, to);
    if (!entry) return false;
    sOut = s(entry);
    worldNormal = normal(entry);
    return true;
  }

 private:
  LhtLookup table_;
  Mat3<T> normalToWorld_;
};

}  // namespace lattice::lht
