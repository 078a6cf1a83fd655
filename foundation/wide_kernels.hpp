#pragma once
// 128-bit products and quotients in 32-bit steps, for a core with no
// 64-bit multiply or divide instruction (the firmware's Cortex-M3: UMULL,
// 32x32->64, and UDIV, 32/32, per Arm's Cortex-M3 Technical Reference
// Manual, "Instruction set summary"). Fixed32's * and / and the portable
// Int128's division (foundation/int128.hpp) use them where GCC has no
// __int128; tests/foundation/wide_kernels_test.cpp checks every kernel
// against __int128 on the host, bit for bit.
//
// Method and tunables (no tunables: every result is fixed by its definition):
// * multiply64: the 128-bit product of two 64-bit values from four 32x32->64
//   products (schoolbook, base 2^32), the middle column summed in 64 bits.
// * divide64By32: (high:low) / d for a normalised 32-bit d (top bit set) and
//   high < d, by Knuth's algorithm D (TAOCP vol. 2, 4.3.1) in base 2^16:
//   two quotient digits, each estimated by one 32/16 UDIV and corrected by
//   the next divisor digit (at most twice), so no 64-bit library division.
// * divide128By64: (high:low) / d for a normalised 64-bit d and high < d,
//   algorithm D in base 2^32 with divide64By32 for each digit's estimate;
//   with a two-digit divisor the second-digit test makes each digit exact.
// * addRaw / subtractRaw: Fixed<F>'s saturated sum and difference.
// * multiplyRaw / divideRaw: Fixed<F>'s rounded, saturated product and
//   quotient of raw values (round half away from zero, symmetric saturation
//   to +-(2^63 - 1)), from the magnitudes, the sign applied last.
//   Magnitudes below 2^32 (below 1.0 in Q31.32: unit vectors, cosines)
//   take shorter paths: a product of two of them is one 32x32->64 product,
//   of one of them and a larger one two (multiply64By32); a quotient by one
//   (n below 2^96) is two divide64By32 digits. A quotient below 2^32 (a
//   result below 1.0: a reciprocal of more than 1.0, a component over a
//   length) is one digit of the long division (divideDigit), where the
//   general path computes a leading zero digit first.
#include <cstdint>

namespace lattice::wide {

struct U128 {
  std::uint64_t high, low;
};

constexpr U128 multiply64(std::uint64_t a, std::uint64_t b) {
  const std::uint32_t a0 = static_cast<std::uint32_t>(a), a1 = static_cast<std::uint32_t>(a >> 32);
  const std::uint32_t b0 = static_cast<std::uint32_t>(b), b1 = static_cast<std::uint32_t>(b >> 32);
  const std::uint64_t p00 = std::uint64_t(a0) * b0, p01 = std::uint64_t(a0) * b1;
  const std::uint64_t p10 = std::uint64_t(a1) * b0, p11 = std::uint64_t(a1) * b1;
  // Below 3 * 2^32: no carry is lost.
  const std::uint64_t middle = (p00 >> 32) + static_cast<std::uint32_t>(p01) + static_cast<std::uint32_t>(p10);
  return {p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), middle << 32 | static_cast<std::uint32_t>(p00)};
}

// The product of a 64-bit and a 32-bit value: two 32x32->64 products.
constexpr U128 multiply64By32(std::uint64_t a, std::uint32_t b) {
  const std::uint64_t p0 = std::uint64_t(static_cast<std::uint32_t>(a)) * b;
  const std::uint64_t p1 = std::uint64_t(static_cast<std::uint32_t>(a >> 32)) * b;
  const std::uint64_t middle = (p0 >> 32) + static_cast<std::uint32_t>(p1);  // below 2^33
  return {(p1 >> 32) + (middle >> 32), middle << 32 | static_cast<std::uint32_t>(p0)};
}

// q = (high:low) / d, rest in `remainder`; d >= 2^31, high < d.
constexpr std::uint32_t divide64By32(std::uint32_t high, std::uint32_t low, std::uint32_t d, std::uint32_t& remainder) {
  constexpr std::uint32_t kBase = 1u << 16, kDigit = kBase - 1;
  const std::uint32_t dHigh = d >> 16, dLow = d & kDigit;
  const std::uint32_t lowDigits[2] = {low >> 16, low & kDigit};
  std::uint32_t partial = high, quotient = 0;
  for (const std::uint32_t next : lowDigits) {
    std::uint32_t q = partial / dHigh, r = partial - q * dHigh;
    while (q >= kBase || q * dLow > (r << 16 | next)) {
      --q;
      r += dHigh;
      if (r >= kBase) break;
    }
    partial = (partial << 16 | next) - q * d;  // modulo 2^32: the true rest is below d
    quotient = quotient << 16 | q;
  }
  remainder = partial;
  return quotient;
}

// One base-2^32 digit of a long division: q = (partial:next) / d for a
// normalised d (d >= 2^63) and partial < d; partial becomes the rest.
constexpr std::uint32_t divideDigit(std::uint64_t& partial, std::uint32_t next, std::uint64_t d) {
  const std::uint32_t dHigh = static_cast<std::uint32_t>(d >> 32), dLow = static_cast<std::uint32_t>(d);
  const std::uint32_t top = static_cast<std::uint32_t>(partial >> 32), second = static_cast<std::uint32_t>(partial);
  // Estimate from (top:second) / dHigh; top <= dHigh since partial < d.
  std::uint32_t q;
  std::uint64_t r;  // the estimate's rest, (top:second) - q dHigh, may reach 2^32
  if (top >= dHigh) {
    q = 0xffffffffu;
    r = std::uint64_t(second) + dHigh;  // (top:second) - (2^32 - 1) dHigh with top == dHigh
  } else {
    std::uint32_t rest = 0;
    q = divide64By32(top, second, dHigh, rest);
    r = rest;
  }
  // With a two-digit divisor this test is exact: q d > (partial:next) iff it holds.
  while (r >> 32 == 0 && std::uint64_t(q) * dLow > (r << 32 | next)) {
    --q;
    r += dHigh;
  }
  // The new rest is below d: modulo 2^64 is exact.
  partial = (partial << 32 | next) - (std::uint64_t(q) * dLow + (std::uint64_t(q * dHigh) << 32));
  return q;
}

// q = (high:low) / d, rest in `remainder`; d >= 2^63, high < d.
constexpr std::uint64_t divide128By64(std::uint64_t high, std::uint64_t low, std::uint64_t d, std::uint64_t& remainder) {
  std::uint64_t partial = high;  // the running rest, < d
  const std::uint32_t qHigh = divideDigit(partial, static_cast<std::uint32_t>(low >> 32), d);
  const std::uint32_t qLow = divideDigit(partial, static_cast<std::uint32_t>(low), d);
  remainder = partial;
  return std::uint64_t(qHigh) << 32 | qLow;
}

constexpr std::uint64_t magnitude(std::int64_t v) { return v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v); }
inline constexpr std::uint64_t kMaxRaw = (std::uint64_t(1) << 63) - 1;
constexpr std::int64_t signedRaw(std::uint64_t m, bool negative) {
  if (m > kMaxRaw) m = kMaxRaw;
  const auto v = static_cast<std::int64_t>(m);
  return negative ? -v : v;
}

// a + b and a - b saturated to +-(2^63 - 1), from the 64-bit sum and its
// overflow flag (ADDS/ADC and the V flag on ARM) instead of a 128-bit sum
// and two 128-bit compares.
constexpr std::int64_t addRaw(std::int64_t a, std::int64_t b) {
  std::int64_t sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) return a > 0 ? static_cast<std::int64_t>(kMaxRaw) : -static_cast<std::int64_t>(kMaxRaw);
  return sum < -static_cast<std::int64_t>(kMaxRaw) ? -static_cast<std::int64_t>(kMaxRaw) : sum;
}
constexpr std::int64_t subtractRaw(std::int64_t a, std::int64_t b) {
  std::int64_t difference = 0;
  if (__builtin_sub_overflow(a, b, &difference))
    return a >= 0 ? static_cast<std::int64_t>(kMaxRaw) : -static_cast<std::int64_t>(kMaxRaw);
  return difference < -static_cast<std::int64_t>(kMaxRaw) ? -static_cast<std::int64_t>(kMaxRaw) : difference;
}

// round(a b / 2^F), halves away from zero, saturated to +-(2^63 - 1).
template <int F>
constexpr std::int64_t multiplyRaw(std::int64_t a, std::int64_t b) {
  static_assert(F > 0 && F < 64, "fraction bits of a 64-bit raw value");
  const std::uint64_t ua = magnitude(a), ub = magnitude(b);
  const bool negative = (a < 0) != (b < 0);
  if ((ua | ub) >> 32 == 0) {
    // Both below 2^32 (|x| < 1 in Q31.32): one 32x32->64 product, which
    // cannot saturate for F >= 1.
    const std::uint64_t p = std::uint64_t(static_cast<std::uint32_t>(ua)) * static_cast<std::uint32_t>(ub);
    return signedRaw(((p >> (F - 1)) + 1) >> 1, negative);  // round(p / 2^F): halves up
  }
  const U128 p = ub >> 32 == 0   ? multiply64By32(ua, static_cast<std::uint32_t>(ub))
                 : ua >> 32 == 0 ? multiply64By32(ub, static_cast<std::uint32_t>(ua))
                                 : multiply64(ua, ub);
  // + 2^(F-1), then the bits from F up.
  const std::uint64_t low = p.low + (std::uint64_t(1) << (F - 1));
  const std::uint64_t high = p.high + (low < p.low ? 1 : 0);
  if (high >> (F - 1) != 0) return signedRaw(~std::uint64_t(0), negative);  // >= 2^63 after the shift
  return signedRaw(high << (64 - F) | low >> F, negative);
}

// round(a 2^F / b), halves away from zero, saturated; b == 0 gives the
// saturated value with a's sign (0 for 0 / 0).
template <int F>
constexpr std::int64_t divideRaw(std::int64_t a, std::int64_t b) {
  static_assert(F > 0 && F < 64, "fraction bits of a 64-bit raw value");
  if (b == 0) return a > 0 ? static_cast<std::int64_t>(kMaxRaw) : (a < 0 ? -static_cast<std::int64_t>(kMaxRaw) : 0);
  const bool negative = (a < 0) != (b < 0);
  const std::uint64_t ua = magnitude(a), ud = magnitude(b);
  // n = ua 2^F + floor(ud / 2), at most 2^(63+F) + 2^62: below 2^127.
  const std::uint64_t half = ud >> 1;
  const std::uint64_t nLow0 = ua << F;
  const std::uint64_t nLow = nLow0 + half;
  const std::uint64_t nHigh = (ua >> (64 - F)) + (nLow < nLow0 ? 1 : 0);
  // The quotient is at least 2^63 (saturated) iff floor(n / 2^63) >= ud.
  if ((nHigh << 1 | nLow >> 63) >= ud) return signedRaw(~std::uint64_t(0), negative);
  if ((nHigh | ud) >> 32 == 0) {
    // A 96-bit n over a 32-bit divisor (a divisor below 1.0 in Q31.32):
    // two 32-bit quotient digits, each one divide64By32 on the normalised
    // divisor, instead of two rounds of the 128/64 long division.
    const auto d = static_cast<std::uint32_t>(ud);
    const auto n2 = static_cast<std::uint32_t>(nHigh), n1 = static_cast<std::uint32_t>(nLow >> 32);
    const auto n0 = static_cast<std::uint32_t>(nLow);
    const int s = __builtin_clz(d);
    const std::uint32_t dn = d << s;
    // n2 < d (the quotient is below 2^63), so the quotient's top digit is 0
    // and the next two come from (n2:n1:n0) 2^s over dn.
    const std::uint32_t top = s == 0 ? n2 : (n2 << s | n1 >> (32 - s));
    const std::uint32_t middle = s == 0 ? n1 : (n1 << s | n0 >> (32 - s));
    std::uint32_t rest = middle;
    // A quotient below 2^32 has a zero top digit: (top:middle) < dn.
    const std::uint32_t qHigh = top == 0 && middle < dn ? 0 : divide64By32(top, middle, dn, rest);
    const std::uint32_t qLow = divide64By32(rest, n0 << s, dn, rest);
    return signedRaw(std::uint64_t(qHigh) << 32 | qLow, negative);
  }
  // Normalised: n 2^s < 2^63 (ud 2^s), so its high half is below ud 2^s.
  const int s = __builtin_clzll(ud);
  const std::uint64_t high = s == 0 ? nHigh : (nHigh << s | nLow >> (64 - s)), low = nLow << s, dn = ud << s;
  // A quotient below 2^32 iff floor(n 2^s / 2^32) < dn: its one digit.
  if (high >> 32 == 0) {
    std::uint64_t partial = high << 32 | low >> 32;
    if (partial < dn) return signedRaw(divideDigit(partial, static_cast<std::uint32_t>(low), dn), negative);
  }
  std::uint64_t rest = 0;
  return signedRaw(divide128By64(high, low, dn, rest), negative);
}

}  // namespace lattice::wide
