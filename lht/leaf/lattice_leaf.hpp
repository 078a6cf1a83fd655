#pragma once
// A lattice as a CSG leaf (thesis sec. 3.2.2): the ray is carried into
// lattice coordinates by the leaf's own transform, clipped to the lattice
// box, its entry and exit rounded to the nearest grid points p_i and p_o, and
// the LHT answers: (p_i, p_o) gives where the ray enters the object, (p_o,
// p_i) where it leaves. So a lattice yields a span like any other solid and
// takes part in union, intersection and difference. firstHit, firstEnter
// and anyHit give what that span would without building it, reading the
// leaving pair only when the entry does not settle the answer
// (docs/lattices.md, "The leaf's queries").
#include <memory>

#include "lht/leaf/lookup_mode.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/leaf/lookup_stats.hpp"
#include "render/shapes/primitive.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice::lht {

// table: the rasterized lattice (shared by every instance of it).
// objectToWorld: places the lattice's object; the lattice box's own map
// (lattice -> object) is applied first.
// castsShadows false: anyHit() (shadow rays) never reports this lattice, so
// lattices shade like a particle system (thesis plate 3).
// Shadow rays leaving a lattice's own surface: rounding p_i and p_o moves
// the looked-up surface by up to half a cell, so a span that ends within one
// cell (measured along the ray) after tmin is taken as the surface the ray
// starts on and dropped; without that, every lit lattice point would shadow
// itself ("acne"). Crossings further away - another part of the same object,
// another lattice - shadow as usual.
// stats: null, or where every look-up is counted (`render --lht-stats`).
// lookup: how a ray becomes look-ups (lht/leaf/lookup_mode.hpp).
template <typename T>
PrimitivePtr<T> makeLatticeLeaf(std::shared_ptr<const LhtFile> table, const Mat4d& objectToWorld, MaterialId material,
                                bool castsShadows = true, LookupStats* stats = nullptr,
                                LatticeLookup lookup = LatticeLookup::Thesis);

#define LATTICE_DECLARE(T)                                                                                  \
  extern template PrimitivePtr<T> makeLatticeLeaf<T>(std::shared_ptr<const LhtFile>, const Mat4d&, MaterialId, bool, \
                                                     LookupStats*, LatticeLookup);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice::lht
