#pragma once
// The LHT entry precision: how many bits a lattice hash table entry spends on
// the hit fraction s and on the unit normal, trading table memory for the
// picture's closeness to the full ray trace (docs/lattices.md, "Entry
// precision"). Every form keeps the thesis's 6-byte key (p_i, p_o) first and
// its 4-byte overflow index last; only the payload between them differs.
//
//   form     bytes  s                normal                         error bounds (s, normal angle)
//   thesis   14     u8,  s * 255     3 x i8, n * 127 (thesis 2.3)   1/510,    0.391 degrees
//   wide     16     u16, s * 65535   octahedral 2 x i16 (+-32767)   1/131070, 0.0026 degrees
//   compact  13     u8,  s * 255     octahedral 2 x i8  (+-127)     1/510,    0.65 degrees
//
// The s bounds are half a quantization step (we round to nearest). The
// normal bound is the largest angle between a unit normal and its decoded
// direction: for the thesis's entry asin(sqrt(3) / 254) (each component off
// by at most 1/254; measured 0.388 degrees), for the octahedral forms the
// largest error over 20 million directions (0.00247 and 0.637 degrees)
// rounded up. tests/lht/entry_codec_test.cpp checks them.
//
// A precision is a plain value: a lattice definition carries one, code may
// set it before the table is built (a memory budget can pick the form that
// fits from entryBytes()).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace lattice::lht {

// The values are the codes stored in a .lht file's header (offset 18);
// version-1 files had 0 there, which is the thesis's entry.
enum class LhtPrecision : std::uint16_t {
  Thesis = 0,
  Wide = 1,
  Compact = 2,
};

struct LhtPrecisionInfo {
  LhtPrecision precision;
  std::string_view name;         // as in scene files and on the command line
  std::size_t entryBytes;        // the slot stride: key 6 + payload + next 4
  std::uint32_t sSteps;          // s is stored as round(s * sSteps)
  double maxSError;              // |decoded s - s| <= this (half a step)
  double maxNormalErrorDegrees;  // angle between a unit normal and its decoded direction
  std::string_view summary;      // one line for --help and lht-info
};

inline constexpr std::array<LhtPrecisionInfo, 3> kLhtPrecisions = {{
    {LhtPrecision::Thesis, "thesis", 14, 255, 0.5 / 255, 0.391,
     "s in 8 bits, normal as 3 signed bytes (thesis sec. 2.3)"},
    {LhtPrecision::Wide, "wide", 16, 65535, 0.5 / 65535, 0.0026,
     "s in 16 bits, normal octahedral in 2 x 16 bits"},
    {LhtPrecision::Compact, "compact", 13, 255, 0.5 / 255, 0.65,
     "s in 8 bits, normal octahedral in 2 x 8 bits"},
}};

const LhtPrecisionInfo& lhtPrecisionInfo(LhtPrecision precision);

// Bytes of one table slot (entry) of this precision.
inline std::size_t entryBytes(LhtPrecision precision) { return lhtPrecisionInfo(precision).entryBytes; }

std::string_view lhtPrecisionName(LhtPrecision precision);
// "thesis (14 B/entry), wide (16 B/entry), compact (13 B/entry)": for messages.
std::string lhtPrecisionChoices();
// nullopt for an unknown name.
std::optional<LhtPrecision> lhtPrecisionFromName(std::string_view name);
// Throws lattice::Error(Usage) naming `what` (e.g. "--lht-precision") and the valid names.
LhtPrecision parseLhtPrecision(std::string_view name, std::string_view what = "LHT precision");
// The form a .lht header's code stands for; nullopt for an unknown code.
std::optional<LhtPrecision> lhtPrecisionFromCode(std::uint16_t code);

}  // namespace lattice::lht
