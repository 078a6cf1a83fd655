#pragma once
// 128-bit integers for targets whose compiler has no __int128 (32-bit ARM:
// the firmware's Cortex-M3, docs/firmware.md). Fixed32's products and
// quotients, its square roots and the fixed-point root solver all compute in
// 128 bits; where GCC offers __int128 (every 64-bit host) foundation/fixed.hpp
// uses it, and this class stands in elsewhere with the same results bit for
// bit, so a fixed-point picture is identical on the host and the MCU.
//
// Method: two 64-bit halves in two's complement. Multiplication is the
// schoolbook product of 32-bit digits (four 32x32->64 multiplies for the low
// half, the cross terms modulo 2^64). Division: the 64-bit hardware (or
// libgcc) division when both operands fit in 64 bits (libgcc's has quick
// paths for small operands); a divisor that fits in 64 bits (all of
// Fixed32's quotients and square roots) by foundation/wide_kernels.hpp's
// long division in base 2^32 on the normalised divisor (Knuth, TAOCP vol.
// 2, 4.3.1, algorithm D), each digit estimated with 32/16-bit UDIVs; wider divisors by shift-and-subtract over the quotient's
// possible bits. Bit lengths come from count-leading-zeros (one CLZ on ARMv7-M). Semantics follow GCC's
// __int128: wrap-around modulo 2^128, division truncates towards zero,
// right shifts of signed values are arithmetic. Shift counts are 0..127.
// tests/foundation/int128_test.cpp compares every operator with __int128.
#include <compare>
#include <concepts>
#include <cstdint>
#include <type_traits>

#include "foundation/wide_kernels.hpp"

namespace lattice {

template <bool Signed>
class Wide128 {
 public:
  constexpr Wide128() = default;
  template <std::integral I>
  constexpr Wide128(I v)  // NOLINT: implicit, like the built-in integer conversions
      : lo_(static_cast<std::uint64_t>(v)), hi_(std::is_signed_v<I> && v < 0 ? ~std::uint64_t(0) : 0) {}
  constexpr explicit Wide128(Wide128<!Signed> other) : lo_(other.low()), hi_(other.high()) {}
  static constexpr Wide128 fromHalves(std::uint64_t high, std::uint64_t low) {
    Wide128 w;
    w.hi_ = high;
    w.lo_ = low;
    return w;
  }

  constexpr std::uint64_t low() const { return lo_; }
  constexpr std::uint64_t high() const { return hi_; }
  template <std::integral I>
  constexpr explicit operator I() const {
    return static_cast<I>(lo_);
  }
  constexpr bool negative() const { return Signed && (hi_ >> 63) != 0; }

  friend constexpr bool operator==(Wide128 a, Wide128 b) = default;
  friend constexpr std::strong_ordering operator<=>(Wide128 a, Wide128 b) {
    if (a.hi_ != b.hi_) {
      if constexpr (Signed) return static_cast<std::int64_t>(a.hi_) <=> static_cast<std::int64_t>(b.hi_);
      return a.hi_ <=> b.hi_;
    }
    return a.lo_ <=> b.lo_;
  }

  friend constexpr Wide128 operator+(Wide128 a, Wide128 b) {
    const std::uint64_t low = a.lo_ + b.lo_;
    return fromHalves(a.hi_ + b.hi_ + (low < a.lo_ ? 1 : 0), low);
  }
  friend constexpr Wide128 operator-(Wide128 a, Wide128 b) {
    return fromHalves(a.hi_ - b.hi_ - (a.lo_ < b.lo_ ? 1 : 0), a.lo_ - b.lo_);
  }
  constexpr Wide128 operator-() const { return Wide128() - *this; }
  constexpr Wide128 operator~() const { return fromHalves(~hi_, ~lo_); }
  friend constexpr Wide128 operator*(Wide128 a, Wide128 b) {
    Wide128 p = multiply64(a.lo_, b.lo_);
    p.hi_ += a.lo_ * b.hi_ + a.hi_ * b.lo_;
    return p;
  }
  friend constexpr Wide128 operator/(Wide128 a, Wide128 b) { return divide(a, b, false); }
  friend constexpr Wide128 operator%(Wide128 a, Wide128 b) { return divide(a, b, true); }
  friend constexpr Wide128 operator&(Wide128 a, Wide128 b) { return fromHalves(a.hi_ & b.hi_, a.lo_ & b.lo_); }
  friend constexpr Wide128 operator|(Wide128 a, Wide128 b) { return fromHalves(a.hi_ | b.hi_, a.lo_ | b.lo_); }
  friend constexpr Wide128 operator<<(Wide128 a, int s) {
    if (s == 0) return a;
    if (s >= 64) return fromHalves(a.lo_ << (s - 64), 0);
    return fromHalves(a.hi_ << s | a.lo_ >> (64 - s), a.lo_ << s);
  }
  friend constexpr Wide128 operator>>(Wide128 a, int s) {
    if (s == 0) return a;
    const std::uint64_t fill = a.negative() ? ~std::uint64_t(0) : 0;
    if (s >= 64) {
      const std::uint64_t low = s == 64 ? a.hi_ : (a.hi_ >> (s - 64) | fill << (128 - s));
      return fromHalves(fill, low);
    }
    return fromHalves(a.hi_ >> s | fill << (64 - s), a.lo_ >> s | a.hi_ << (64 - s));
  }

  constexpr Wide128& operator+=(Wide128 o) { return *this = *this + o; }
  constexpr Wide128& operator-=(Wide128 o) { return *this = *this - o; }
  constexpr Wide128& operator*=(Wide128 o) { return *this = *this * o; }
  constexpr Wide128& operator/=(Wide128 o) { return *this = *this / o; }
  constexpr Wide128& operator<<=(int s) { return *this = *this << s; }
  constexpr Wide128& operator>>=(int s) { return *this = *this >> s; }
  constexpr Wide128& operator++() { return *this += 1; }
  constexpr Wide128& operator--() { return *this -= 1; }

 private:
  // The full 128-bit product of two 64-bit values from 32-bit digits.
  static constexpr Wide128 multiply64(std::uint64_t a, std::uint64_t b) {
    const std::uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    const std::uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    return fromHalves(p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), (middle << 32) | (p00 & 0xffffffffu));
  }
  static constexpr int bitLength64(std::uint64_t v) { return v == 0 ? 0 : 64 - __builtin_clzll(v); }
  static constexpr int bitLength(Wide128 v) { return v.hi_ != 0 ? 64 + bitLength64(v.hi_) : bitLength64(v.lo_); }
  // (high:low) / d and its remainder for high < d, d != 0: d shifted left
  // until its top bit is set, then foundation/wide_kernels.hpp's algorithm D
  // in 32-bit steps (no 64-bit library division).
  static constexpr std::uint64_t divide128By64(std::uint64_t high, std::uint64_t low, std::uint64_t d,
                                               std::uint64_t& remainder) {
    const int s = __builtin_clzll(d);
    const std::uint64_t top = s == 0 ? high : (high << s | low >> (64 - s));  // < d after the shift
    const std::uint64_t quotient = wide::divide128By64(top, low << s, d << s, remainder);
    remainder >>= s;
    return quotient;
  }
  // Unsigned magnitudes; the quotient or the remainder (remainder = true).
  static constexpr Wide128<false> divideUnsigned(Wide128<false> n, Wide128<false> d, bool remainder) {
    if (d.high() == 0 && n.high() == 0) {
      if (d.low() == 0) return 0;  // as undefined as the built-in; never asked by callers
      return remainder ? n.low() % d.low() : n.low() / d.low();
    }
    if (n < d) return remainder ? n : Wide128<false>();
    if (d.high() == 0) {
      // Long division by a 64-bit divisor: the high half first (a 64-bit
      // division only when the quotient needs more than 64 bits, which
      // Fixed32 never asks), then the rest in 32-bit steps.
      std::uint64_t qHigh = 0, top = n.high();
      if (top >= d.low()) {
        qHigh = top / d.low();
        top %= d.low();
      }
      std::uint64_t r = 0;
      const std::uint64_t qLow = divide128By64(top, n.low(), d.low(), r);
      return remainder ? Wide128<false>(r) : Wide128<false>::fromHalves(qHigh, qLow);
    }
    const int shift = bitLength(Wide128(n)) - bitLength(Wide128(d));
    Wide128<false> q, r = n, m = d << shift;
    for (int i = shift; i >= 0; --i) {
      q <<= 1;
      if (r >= m) {
        r -= m;
        q += 1;
      }
      m >>= 1;
    }
    return remainder ? r : q;
  }
  static constexpr Wide128 divide(Wide128 a, Wide128 b, bool remainder) {
    const bool na = a.negative(), nb = b.negative();
    const Wide128<false> ua(na ? -a : a), ub(nb ? -b : b);
    const Wide128 r(divideUnsigned(ua, ub, remainder));
    // Truncation towards zero: the quotient's sign is the signs' product,
    // the remainder's the dividend's.
    const bool flip = remainder ? na : na != nb;
    return flip ? -r : r;
  }

  std::uint64_t lo_ = 0;
  std::uint64_t hi_ = 0;
};

}  // namespace lattice
