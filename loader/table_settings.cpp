#include "loader/table_settings.hpp"

#include "lht/table/table_forms.hpp"

namespace lattice::lht {

namespace {

using T = TableSettings;

// The word for "each lattice's own": what its scene file says.
constexpr std::string_view kEachLattice = "scene";

// Each help line says why a user would set it.
constexpr lattice::Setting<T> kTableRows[] = {
    orUnset(choiceInOrder<kLhtPrecisions, &T::precision>(
                "lht-precision", "every lattice's entry precision: thesis (14 B an entry, s in 8 bits), wide (16 B, "
                                 "the most accurate normals) or compact (13 B, the smallest table); docs/lattices.md"),
            kEachLattice),
    orUnset(choiceInOrder<kLhtFormNames, &T::form>(
                "lht-form", "every lattice's table form: hashed (the thesis's), compressed (about half the memory) "
                            "or on-demand (nothing rasterized up front: only the pairs a render asks); "
                            "docs/lattices.md"),
            kEachLattice),
    orUnset(choiceOf<kLatticeLookupNames, &T::lookup>(
                "lattice-lookup", "how every lattice leaf reads its table: thesis (the nearest lattice points, one "
                                  "pair) or blend (the 16 pairs around the ray, weighted: smoother edges, slower)"),
            kEachLattice),
    bytes<&T::onDemandCacheBytes>(
        "lht-cache", "with the on-demand form: the most memory its stored answers take (48 B each; misses go to a "
                     "bitmap apart); beyond it new pairs are traced again rather than stored"),
};

constexpr SettingsSchema<T> kTableSchema{"lattice tables", kTableRows, [] { return T{}; }};

}  // namespace

const SettingsSchema<TableSettings>& tableSettings() { return kTableSchema; }

}  // namespace lattice::lht
