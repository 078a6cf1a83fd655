#pragma once
// The .lht file: a rasterized lattice saved so a scene need not rasterize it
// again. Layout (all integers little-endian, reals IEEE-754 binary64):
//
//   offset size
//        0    8  magic "LATLHT\r\n" (the CR LF catches text-mode mangling)
//        8    4  version: 4 for the hashed form (kLhtVersion), 3 for the
//                compressed one (kLhtCompressedVersion); 1 and 2, and 3's
//                hashed form (the thesis's chained table), are no longer
//                read: a scene's cache in one is rebuilt
//       12    6  cells along x, y, z (u16 each, 1..255)
//       18    2  entry precision code (LhtPrecision: 0 thesis, 1 wide, 2 compact)
//       20    8  lambda (object units)
//       28    8  f_lat
//       36   24  lattice origin in object coordinates (x, y, z)
//       60    8  object hash (FNV-1a 64 of the object's definition)
//       68    8  N_lp (pairs, as eq. 1.3 counts them)
//       76    8  N_iz (hitting pairs, same counting)
//       84    8  entries
//       92    8  capacity (slots)
//      100    8  slots (the same number)
//      108  e*n  the n slots of lht/table/hash_table.hpp's open-addressed
//                table, e = LatticeHashTable::slotStride(precision) bytes
//                each, an empty slot all zero, as in memory and in the
//                firmware's flash
//      end    8  FNV-1a 64 of every byte before it
//
// That is version 4, the hashed form. Version 3 adds 8 header bytes and the
// body of another form:
//      108    2  form code (LhtForm: 1 compressed; 0, hashed, was chained)
//      110    2  pair layout (PairLayout: 0 symmetric, 1 ordered)
//      112    4  reserved, 0
//   any other form (lht/table/table_forms.hpp): fields 84, 92, 100 and 110
//   are its LhtBodyHeader, and its body runs from byte 116 to the checksum.
//   compressed: field 92 holds the bitmap's bits (which the cells and the
//   layout decide; a mismatch is refused) and field 100 its 64-bit words;
//   the body is the words (8 bytes each), then `entries` payloads of
//   payloadBytes(precision) bytes.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "foundation/fnv1a.hpp"
#include "foundation/system/atomic_file.hpp"
#include "lht/grid/lattice_box.hpp"
#include "lht/table/table_forms.hpp"

namespace lattice::lht {

inline constexpr std::uint32_t kLhtVersion = 4;            // hashed tables are written so (open-addressed)
inline constexpr std::uint32_t kLhtCompressedVersion = 3;  // compressed tables are written so
inline constexpr std::size_t kLhtHeaderBytes = 108;
inline constexpr std::size_t kLhtHeaderBytesV3 = 116;

// The table is one of the forms of lht/table/table_forms.hpp's list; the
// alternative's index is its LhtForm code, so the form is never stored apart
// from the table it names. The named forms' positions:
static_assert(std::is_same_v<FormAt<static_cast<std::size_t>(LhtForm::Hashed)>, LatticeHashTable>);
static_assert(std::is_same_v<FormAt<static_cast<std::size_t>(LhtForm::Compressed)>, CompressedTable>);
static_assert(std::is_same_v<FormAt<static_cast<std::size_t>(LhtForm::OnDemand)>, OnDemandTable>);

struct LhtFile {
  std::uint32_t version = kLhtVersion;  // as read; written: kLhtVersion, or kLhtCompressedVersion when compressed
  LatticeBox box{{1, 1, 1}, 1.0, 1.0, Vec3d(0.0)};
  std::uint64_t objectHash = 0;
  std::uint64_t pairs = 0;  // N_lp
  std::uint64_t hits = 0;   // N_iz
  LhtTable table;           // hashed unless set otherwise

  LhtForm form() const { return static_cast<LhtForm>(table.index()); }
  // The table as the given form; throws std::bad_variant_access for another form.
  const LatticeHashTable& hashed() const { return std::get<LatticeHashTable>(table); }
  const CompressedTable& compressed() const { return std::get<CompressedTable>(table); }
  const OnDemandTable& onDemand() const { return *std::get<std::shared_ptr<const OnDemandTable>>(table); }

  LhtPrecision precision() const {
    return std::visit([](const auto& t) { return formTable(t).precision(); }, table);
  }
  // Entries held (on demand: the hits stored so far).
  std::uint64_t entryCount() const {
    return std::visit([](const auto& t) { return formTable(t).entryCount(); }, table);
  }
  // The table's bytes in memory (compressed: with its rank directory; on demand: so far).
  std::uint64_t tableBytes() const {
    return std::visit([](const auto& t) { return formTable(t).bytes(); }, table);
  }
};

std::vector<std::uint8_t> serializeLht(const LhtFile& lht);
// `name` is used in messages. With expectedObjectHash, a file rasterized
// from another object definition is refused; with expectedPrecision, a file
// whose entries have another precision (a cache must not silently give a
// picture of another accuracy than asked for); with expectedForm, a file of
// the other form.
LhtFile parseLht(std::span<const std::uint8_t> bytes, const std::string& name,
                 std::optional<std::uint64_t> expectedObjectHash = std::nullopt,
                 std::optional<LhtPrecision> expectedPrecision = std::nullopt,
                 std::optional<LhtForm> expectedForm = std::nullopt);

// Atomically; a cache beside a scene says Landing::Now, so it is kept even
// when the command that built it fails later (foundation/system/output_transaction.hpp).
void writeLhtFile(const std::filesystem::path& path, const LhtFile& lht,
                  AtomicFile::Landing landing = AtomicFile::Landing::WithCommand);
LhtFile readLhtFile(const std::filesystem::path& path, std::optional<std::uint64_t> expectedObjectHash = std::nullopt,
                    std::optional<LhtPrecision> expectedPrecision = std::nullopt,
                    std::optional<LhtForm> expectedForm = std::nullopt);
// The version of a file an older Lattice wrote in a layout this one no
// longer reads (a cache to rebuild, with a note); nullopt for anything else.
std::optional<std::uint32_t> retiredLhtVersion(const std::filesystem::path& path);

}  // namespace lattice::lht
