#pragma once
// How a lattice leaf turns a ray into table look-ups (lht/leaf/lattice_leaf.cpp).
//
//   thesis  the thesis's look-up (sec. 2.1, 3.2.2): both ends of the ray's
//           chord through the lattice box rounded to the nearest lattice
//           point, one pair (p_i, p_o) read
//   blend   the chord's ends keep their fraction: on the box face each end
//           lies on, the (up to) four lattice points around it are taken
//           with bilinear weights, and the (up to) 16 pairs between them are
//           read; the ray hits when the hitting pairs hold at least half the
//           weight; s and the normal where it enters are the weighted means
//           over those pairs, where it leaves is read from the heaviest of
//           them. Same table, same size; a 4-D multilinear interpolation of
//           what the table samples (docs/lattices.md, "Look-ups"). Pairs
//           are read heaviest first and a miss is decided as soon as the
//           missing pairs hold over half the weight.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "foundation/name_table.hpp"

namespace lattice::lht {

enum class LatticeLookup { Thesis, Blend };

// The one spelling of each look-up, in scene files and on the command line.
inline constexpr std::array<EnumName<LatticeLookup>, 2> kLatticeLookupNames = {{
    {LatticeLookup::Thesis, "thesis"},
    {LatticeLookup::Blend, "blend"},
}};

std::string_view latticeLookupName(LatticeLookup lookup);
std::string latticeLookupChoices();  // "thesis, blend"
std::optional<LatticeLookup> latticeLookupFromName(std::string_view name);
// Throws lattice::Error(Usage) naming `what` and the valid names.
LatticeLookup parseLatticeLookup(std::string_view name, std::string_view what = "lattice look-up");

}  // namespace lattice::lht
