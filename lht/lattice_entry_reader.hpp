#pragma once
// How a lattice leaf (lht/lattice_leaf.cpp) reads a table entry in its
// arithmetic T: the fraction s along the segment and the world normal.
//
// Method: this generic version serves the IEEE types: the table's decoded
// hit (s and a unit normal in double, LhtLookup::find) converted to T,
// the normal carried to the world by the inverse transpose of
// lattice -> world. An arithmetic that must not go through double
// specialises EntryReader in its own file, as fixed point does
// (lht/lattice_entry_reader_fixed.hpp); the leaf has no per-type branch.
#include "lht/lht_lookup.hpp"
#include "foundation/vec.hpp"

namespace lattice::lht {

template <typename T>
class EntryReader {
 public:
  // Throws lattice::Error(Input) when T cannot follow the lattice placed by
  // latticeToWorld (the generic arithmetics always can).
  EntryReader(const LhtLookup& table, const Mat4d& latticeToWorld)
      : table_(table), normalToWorld_(glm::transpose(Mat3<double>(glm::inverse(latticeToWorld)))) {}

  // The entry of (from, to): false when there is none.
  bool read(const LatticePoint& from, const LatticePoint& to, T& s, Vec3<T>& worldNormal) const {
    const auto hit = table_.find(from, to);
    if (!hit) return false;
    s = T(hit->s);
    worldNormal = lattice::normalize(normalToWorld_ * Vec3<T>(hit->normal));
    return true;
  }

 private:
  LhtLookup table_;
  Mat3<T> normalToWorld_;
};

}  // namespace lattice::lht
