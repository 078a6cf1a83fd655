#include "lht/table/entry_codec.hpp"

#include <algorithm>
#include <cmath>

#include "foundation/rounding.hpp"
#include "lht/grid/octahedral.hpp"

namespace lattice::lht {

namespace {

constexpr std::size_t kPayload = kEntryKeyBytes;  // the payload starts right after the key
constexpr std::int32_t kByteNormalMax = 127;      // signed 8 bits, symmetric so the axes are exact
constexpr std::int32_t kWordNormalMax = 32767;    // signed 16 bits, likewise

void store16(std::uint8_t* p, std::uint32_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
std::uint16_t loadUnsigned16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | p[1] << 8); }
std::int16_t loadSigned16(const std::uint8_t* p) { return static_cast<std::int16_t>(loadUnsigned16(p)); }
std::int8_t loadSigned8(std::uint8_t b) { return static_cast<std::int8_t>(b); }
// The encoder never writes -128 (it clamps to +-127); a forged file might,
// and the direction must stay within normalDirectionMax().
std::int32_t loadNormalByte(std::uint8_t b) { return std::max<std::int32_t>(loadSigned8(b), -kByteNormalMax); }

}  // namespace

std::uint32_t quantizeFraction(double s, std::uint32_t steps) {
  return static_cast<std::uint32_t>(scaledStep(s, 0.0, 1.0, steps));
}

std::int8_t quantizeNormalComponent(double n) {
  return static_cast<std::int8_t>(scaledStep(n, -1.0, 1.0, 127.0));
}

std::int32_t normalDirectionMax(LhtPrecision precision) {
  return precision == LhtPrecision::Wide ? kWordNormalMax : kByteNormalMax;
}

void encodeEntry(const RasterHit& hit, LhtPrecision precision, std::uint8_t* entry) {
  const std::uint8_t key[kEntryKeyBytes] = {hit.in.x, hit.in.y, hit.in.z, hit.out.x, hit.out.y, hit.out.z};
  std::copy(key, key + kEntryKeyBytes, entry);
  encodePayload(hit, precision, entry + kPayload);
}

void encodePayload(const RasterHit& hit, LhtPrecision precision, std::uint8_t* payload) {
  const std::uint32_t s = quantizeFraction(hit.s, lhtPrecisionInfo(precision).sSteps);
  switch (precision) {
    case LhtPrecision::Thesis:
      payload[0] = static_cast<std::uint8_t>(s);
      for (int a = 0; a < 3; ++a) payload[1 + a] = static_cast<std::uint8_t>(quantizeNormalComponent(hit.normal[a]));
      return;
    case LhtPrecision::Wide: {
      store16(payload, s);
      const OctahedralCode code = encodeOctahedral(hit.normal, kWordNormalMax);
      store16(payload + 2, static_cast<std::uint32_t>(code.u));
      store16(payload + 4, static_cast<std::uint32_t>(code.v));
      return;
    }
    case LhtPrecision::Compact: {
      payload[0] = static_cast<std::uint8_t>(s);
      const OctahedralCode code = encodeOctahedral(hit.normal, kByteNormalMax);
      payload[1] = static_cast<std::uint8_t>(code.u);
      payload[2] = static_cast<std::uint8_t>(code.v);
      return;
    }
  }
}

// Integers only: the fixed-point renderer calls this per pixel, and the
// objdump test (tests/lht/fixed_lattice_test.cpp) checks it has no floating point.
EntryIntegers decodeEntryIntegers(const std::uint8_t* entry, LhtPrecision precision) {
  return decodePayloadIntegers(entry + kPayload, precision);
}

EntryIntegers decodePayloadIntegers(const std::uint8_t* payload, LhtPrecision precision) {
  EntryIntegers out;
  switch (precision) {
    case LhtPrecision::Thesis:
      out.sNumerator = payload[0];
      out.sDenominator = 255;
      out.normal = {loadNormalByte(payload[1]), loadNormalByte(payload[2]), loadNormalByte(payload[3])};
      // A zero vector cannot be normalized; the rasterizer never stores one.
      if (out.normal[0] == 0 && out.normal[1] == 0 && out.normal[2] == 0) out.normal = {0, 0, 1};
      break;
    case LhtPrecision::Wide:
      out.sNumerator = loadUnsigned16(payload);
      out.sDenominator = 65535;
      out.normal = decodeOctahedral({loadSigned16(payload + 2), loadSigned16(payload + 4)}, kWordNormalMax);
      break;
    case LhtPrecision::Compact:
      out.sNumerator = payload[0];
      out.sDenominator = 255;
      out.normal = decodeOctahedral({loadSigned8(payload[1]), loadSigned8(payload[2])}, kByteNormalMax);
      break;
  }
  return out;
}

EntryFraction decodePayloadFraction(const std::uint8_t* payload, LhtPrecision precision) {
  if (precision == LhtPrecision::Wide) return {loadUnsigned16(payload), 65535};
  return {payload[0], 255};  // Thesis and Compact: one byte first
}

LhtHit toHit(const EntryIntegers& integers) {
  LhtHit hit;
  hit.s = integers.sNumerator / double(integers.sDenominator);
  const Vec3d n(integers.normal[0], integers.normal[1], integers.normal[2]);
  // Renormalize: quantizing shortens or lengthens the vector (and octahedral
  // directions are not unit length at all).
  hit.normal = n / glm::length(n);
  return hit;
}

}  // namespace lattice::lht
