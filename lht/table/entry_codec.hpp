#pragma once
// One LHT entry as bytes, for every entry precision (lht/table/lht_precision.hpp):
//
//   [0, 6)                 key: p_i (x, y, z), p_o (x, y, z), one byte each
//   [6, entryBytes - 4)    payload: s and the normal, laid out per precision
//   [entryBytes - 4, end)  index of the next entry of the chain (u32, little-endian):
//                          the chained table of .lht versions 1-3 only; the
//                          open-addressed table (lht/table/hash_table.hpp) stores the
//                          first entryBytes - 4 bytes
//
// Entries are packed byte arrays (no padding, multi-byte fields
// little-endian), so a table's bytes in memory are its bytes in a .lht file.
//
// Decoding is integer first: every form yields s as a fraction of integers
// and the normal as an integer direction (EntryIntegers). Fixed-point
// rendering uses those integers directly (no floating point per pixel);
// float and double convert them with toHit(). So there is one decoder per
// form for every arithmetic.
#include <array>
#include <cstddef>
#include <cstdint>

#include "lht/table/lht_precision.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

inline constexpr std::size_t kEntryKeyBytes = 6;
inline constexpr std::size_t kEntryNextBytes = 4;
inline constexpr std::uint32_t kNoNext = 0xFFFFFFFFu;

// A decoded entry in integers: s = sNumerator / sDenominator (in [0, 1]) and
// the normal's direction in lattice coordinates, not unit length but never
// zero, each component within +-normalDirectionMax(precision).
struct EntryIntegers {
  std::int32_t sNumerator = 0;
  std::int32_t sDenominator = 1;
  std::array<std::int32_t, 3> normal{0, 0, 1};
};

// A decoded entry: the hit as the IEEE renderers use it.
struct LhtHit {
  double s = 0.0;
  Vec3d normal{};  // unit, lattice coordinates
};

// Rounded to nearest (the thesis truncated: "a small but acceptable
// truncation error"; rounding halves it): round(clamp(s, 0, 1) * steps).
std::uint32_t quantizeFraction(double s, std::uint32_t steps);
// The thesis's normal component: round(clamp(n, -1, 1) * 127), signed.
std::int8_t quantizeNormalComponent(double n);

// The payload's bytes alone: what the compressed form (no key, no chain,
// lht/table/compressed_table.hpp) stores per entry.
inline std::size_t payloadBytes(LhtPrecision precision) {
  return entryBytes(precision) - kEntryKeyBytes - kEntryNextBytes;
}

// Writes hit's key and payload to entry[0, entryBytes(precision) - 4); the
// overflow index is the table's business.
void encodeEntry(const RasterHit& hit, LhtPrecision precision, std::uint8_t* entry);
// Writes hit's payload alone (payloadBytes(precision) bytes).
void encodePayload(const RasterHit& hit, LhtPrecision precision, std::uint8_t* payload);
// Reads an entry's payload (any bytes: a corrupt payload decodes to some
// valid s and non-zero direction).
EntryIntegers decodeEntryIntegers(const std::uint8_t* entry, LhtPrecision precision);
// The same from the payload's first byte.
EntryIntegers decodePayloadIntegers(const std::uint8_t* payload, LhtPrecision precision);
// s alone as the fraction of integers decodePayloadIntegers() gives, the
// normal left undecoded: what shadow rays and the far end of a chord read.
struct EntryFraction {
  std::int32_t numerator = 0;
  std::int32_t denominator = 1;
};
EntryFraction decodePayloadFraction(const std::uint8_t* payload, LhtPrecision precision);
// The largest |component| decodeEntryIntegers() gives for this precision.
std::int32_t normalDirectionMax(LhtPrecision precision);

LhtHit toHit(const EntryIntegers& integers);
inline LhtHit decodeEntry(const std::uint8_t* entry, LhtPrecision precision) {
  return toHit(decodeEntryIntegers(entry, precision));
}

inline std::uint32_t loadLittleEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
inline void storeLittleEndian32(std::uint8_t* p, std::uint32_t v) {
  for (int b = 0; b < 4; ++b) p[b] = static_cast<std::uint8_t>(v >> (8 * b));
}

}  // namespace lattice::lht
