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
// The values are the codes of a version-3 .lht header (lht/file/lht_file.hpp)
// and the forms' positions in the one list of them, LhtTable
// (lht/table/table_forms.hpp), from which the names come. The enum names the
// forms that code refers to; a new form needs no name here.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "lht/table/lht_precision.hpp"

namespace lattice::lht {

enum class LhtForm : std::uint16_t {
  Hashed = 0,
  Compressed = 1,
  OnDemand = 2,  // in memory only: a .lht file never holds this code
};

// What a version-3 .lht header holds for a form's body (the fields at bytes
// 84, 92, 100 and 110; lht/file/lht_file.hpp), besides the lattice's cells
// and the entry precision every form has.
struct LhtBodyHeader {
  std::array<int, 3> cells{};
  LhtPrecision precision = LhtPrecision::Thesis;
  std::uint64_t entries = 0;
  std::uint64_t countA = 0;   // byte 92: the form's first count (compressed: bitmap bits)
  std::uint64_t countB = 0;   // byte 100: its second (compressed: bitmap words)
  std::uint16_t layout = 0;   // byte 110: its layout code (compressed: PairLayout)
};

std::string_view lhtFormName(LhtForm form);
std::string lhtFormChoices();  // "hashed, compressed, on-demand"
std::optional<LhtForm> lhtFormFromName(std::string_view name);
// A form .lht files hold (version 3), by its code; none for another.
std::optional<LhtForm> lhtFormFromCode(std::uint16_t code);
std::string lhtFiledFormCodes();  // "0 hashed, 1 compressed"
std::string lhtFiledFormNames();  // "hashed or compressed"
// Throws lattice::Error(Usage) naming `what` and the valid names.
LhtForm parseLhtForm(std::string_view name, std::string_view what = "LHT form");

}  // namespace lattice::lht
