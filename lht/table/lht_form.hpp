#pragma once
// The LHT form: how a lattice's hits are indexed, independent of the entry
// precision (lht/table/lht_precision.hpp), which decides the payload's bits.
//
//   hashed      the thesis's table (sec. 2.3): each entry carries its 6-byte
//               key and a 4-byte overflow index (lht/table/hash_table.hpp)
//   compressed  no key, no chain: a rank bitmap over the enumerable pair
//               space says which pairs hit, the payloads follow in pair
//               order (thesis sec. 5.2.1; lht/table/compressed_table.hpp)
//   on-demand   nothing before the first ray: a pair is traced the first
//               time it is asked and its hit or miss kept, within a bound
//               (thesis sec. 5.2.2; lht/table/on_demand_table.hpp); never a file
//
// The values are the codes of a version-3 .lht header (lht/file/lht_file.hpp).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace lattice::lht {

enum class LhtForm : std::uint16_t {
  Hashed = 0,
  Compressed = 1,
  OnDemand = 2,  // in memory only: a .lht file never holds this code
};

std::string_view lhtFormName(LhtForm form);
std::string lhtFormChoices();  // "hashed, compressed, on-demand"
std::optional<LhtForm> lhtFormFromName(std::string_view name);
std::optional<LhtForm> lhtFormFromCode(std::uint16_t code);
// Throws lattice::Error(Usage) naming `what` and the valid names.
LhtForm parseLhtForm(std::string_view name, std::string_view what = "LHT form");

}  // namespace lattice::lht
