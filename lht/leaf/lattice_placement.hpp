#pragma once
// One placed lattice as plain data: everything a lattice leaf
// (lht/leaf/thesis_lattice_leaf.hpp) computes from its transform when it is
// built, so a baked scene can hold it as constant data in flash
// (lht/leaf/baked_lattice_union.hpp, docs/firmware.md) and a leaf made from
// it answers as the leaf it was taken from. Only the table and the lattice's
// box are shared, not held here.
//
// Method: the fields are the leaf's own; a literal type, so `lattice bake`
// can write arrays of it as constexpr data. Tunables: none.
#include "foundation/bounds.hpp"
#include "foundation/vec.hpp"
#include "lht/grid/lattice_chord.hpp"
#include "render/shapes/primitive.hpp"

namespace lattice::lht {

template <typename T>
struct LatticePlacement {
  LatticeAffine<T> worldToLattice;  // world -> lattice coordinates
  Mat3<T> normalMap;                // the entry reader's map of entry normals to world (EntryReader::normalMap)
  Bounds<T> bounds;                 // the lattice box in world space
  MaterialId material = 0;
  bool castsShadows = true;
};

}  // namespace lattice::lht
