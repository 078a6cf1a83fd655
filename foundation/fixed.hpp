#pragma once
// Fixed-point arithmetic for a renderer with no floating-point unit (the
// thesis's Sun 3/60 could run without its 68881). Fixed<F> is a signed 64-bit
// integer holding value * 2^F: with F = 32 (the default, "Q31.32") the range
// is about +-2.1e9 and the resolution 2.3e-10.
//
// Rules, chosen so that overflow never wraps silently:
// - +, -, *, / saturate to the largest representable magnitude on overflow
//   (products and quotients use 128-bit intermediates).
// - Division by zero gives the saturated value with the sign of the dividend
//   (0/0 gives 0): like IEEE infinity, it compares larger than any finite
//   value the renderer uses, so ray code keeps working.
// - Conversions from double round to nearest and saturate; NaN converts to 0.
// - std::numeric_limits<Fixed>::infinity() is the saturated maximum, so code
//   written for float/double that starts searches at "infinity" works.
#include <cstdint>
#include <limits>

#include "foundation/wide_kernels.hpp"

namespace lattice {

// 128-bit intermediates: GCC's __int128 where the target has it (__extension__
// keeps -Wpedantic quiet); on 32-bit targets (the firmware) the portable class
// of foundation/int128.hpp, which gives the same results bit for bit.
// LATTICE_PORTABLE_INT128 forces the portable class on a 64-bit host too, so
// the firmware's arithmetic can be profiled there (docs/firmware.md, Profile).
#if defined(__SIZEOF_INT128__) && !defined(LATTICE_PORTABLE_INT128)
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;
inline constexpr bool kNativeInt128 = true;
#else
inline constexpr bool kNativeInt128 = false;
}  // namespace lattice
#include "foundation/int128.hpp"  // only here: the host's objects never depend on it
namespace lattice {
using Int128 = Wide128<true>;
using UInt128 = Wide128<false>;
#endif

template <int F>
class Fixed {
  static_assert(F > 0 && F < 62, "fraction bits must leave room for an integer part");

 public:
  using Raw = std::int64_t;
  static constexpr int kFractionBits = F;
  static constexpr Raw kOne = Raw(1) << F;
  static constexpr Raw kMaxRaw = std::numeric_limits<Raw>::max();
  static constexpr Raw kMinRaw = -kMaxRaw;  // symmetric, so negation never overflows

  constexpr Fixed() = default;
  constexpr Fixed(int v) : raw_(saturate(static_cast<Int128>(v) << F)) {}  // NOLINT: implicit like a number
  constexpr explicit Fixed(double v) : raw_(fromDouble(v)) {}
  constexpr explicit Fixed(float v) : raw_(fromDouble(static_cast<double>(v))) {}

  static constexpr Fixed fromRaw(Raw raw) {
    Fixed f;
    f.raw_ = raw < kMinRaw ? kMinRaw : raw;
    return f;
  }
  constexpr Raw raw() const { return raw_; }
  constexpr double toDouble() const { return static_cast<double>(raw_) / static_cast<double>(kOne); }
  constexpr explicit operator double() const { return toDouble(); }
  constexpr explicit operator float() const { return static_cast<float>(toDouble()); }
  constexpr explicit operator int() const { return static_cast<int>(raw_ >> F); }  // floor
  constexpr bool saturated() const { return raw_ == kMaxRaw || raw_ == kMinRaw; }

  // Without __int128 every operator below runs foundation/wide_kernels.hpp's
  // 32-bit-step kernels, which give these definitions' bits
  // (tests/foundation/wide_kernels_test.cpp) without the portable class's
  // general 128-bit sums, products, negations and compares (docs/firmware.md,
  // "Speed, bit for bit").
  friend constexpr Fixed operator+(Fixed a, Fixed b) {
    if constexpr (!kNativeInt128) return fromRaw(wide::addRaw(a.raw_, b.raw_));
    return fromRaw(saturate(static_cast<Int128>(a.raw_) + b.raw_));
  }
  friend constexpr Fixed operator-(Fixed a, Fixed b) {
    if constexpr (!kNativeInt128) return fromRaw(wide::subtractRaw(a.raw_, b.raw_));
    return fromRaw(saturate(static_cast<Int128>(a.raw_) - b.raw_));
  }
  constexpr Fixed operator-() const { return fromRaw(-raw_); }
  constexpr Fixed operator+() const { return *this; }
  friend constexpr Fixed operator*(Fixed a, Fixed b) {
    if constexpr (!kNativeInt128) return fromRaw(wide::multiplyRaw<F>(a.raw_, b.raw_));
    Int128 p = static_cast<Int128>(a.raw_) * b.raw_;
    // Round to nearest, ties away from zero, so a*b and (-a)*b are mirror images.
    Int128 half = static_cast<Int128>(1) << (F - 1);
    p = p >= 0 ? (p + half) >> F : -((-p + half) >> F);
    return fromRaw(saturate(p));
  }
  friend constexpr Fixed operator/(Fixed a, Fixed b) {
    if constexpr (!kNativeInt128) return fromRaw(wide::divideRaw<F>(a.raw_, b.raw_));
    if (b.raw_ == 0) return fromRaw(a.raw_ > 0 ? kMaxRaw : (a.raw_ < 0 ? kMinRaw : 0));
    Int128 n = static_cast<Int128>(a.raw_) << F;
    Int128 d = b.raw_;
    bool negative = (n < 0) != (d < 0);
    Int128 un = n < 0 ? -n : n, ud = d < 0 ? -d : d;
    Int128 q = (un + ud / 2) / ud;  // round to nearest
    return fromRaw(saturate(negative ? -q : q));
  }
  constexpr Fixed& operator+=(Fixed o) { return *this = *this + o; }
  constexpr Fixed& operator-=(Fixed o) { return *this = *this - o; }
  constexpr Fixed& operator*=(Fixed o) { return *this = *this * o; }
  constexpr Fixed& operator/=(Fixed o) { return *this = *this / o; }

  friend constexpr auto operator<=>(Fixed a, Fixed b) = default;
  friend constexpr bool operator==(Fixed a, Fixed b) = default;

 private:
  static constexpr Raw saturate(Int128 v) {
    if (v > kMaxRaw) return kMaxRaw;
    if (v < kMinRaw) return kMinRaw;
    return static_cast<Raw>(v);
  }
  static constexpr Raw fromDouble(double v) {
    if (v != v) return 0;
    double scaled = v * static_cast<double>(kOne);
    if (scaled >= 9.2233720368547758e18) return kMaxRaw;
    if (scaled <= -9.2233720368547758e18) return kMinRaw;
    return static_cast<Raw>(scaled >= 0 ? scaled + 0.5 : scaled - 0.5);
  }

  // No default member initializer: GLM keeps vector components in unions,
  // which need a trivial default constructor. Value-initialization (Fixed())
  // still gives 0.
  Raw raw_;
};

using Fixed32 = Fixed<32>;

template <int F>
constexpr Fixed<F> abs(Fixed<F> x) {
  return x < Fixed<F>() ? -x : x;
}

// Bits in n (0 for 0), from count-leading-zeros of its halves (one CLZ
// instruction on ARMv7-M, where a loop took a 128-bit shift a bit).
constexpr int bitLength(UInt128 n) {
  const auto high = static_cast<std::uint64_t>(n >> 64), low = static_cast<std::uint64_t>(n);
  if (high != 0) return 128 - __builtin_clzll(high);
  return low != 0 ? 64 - __builtin_clzll(low) : 0;
}

// floor(sqrt(x)) of a 32-bit integer, digit by digit (two bits of x a
// result bit, from the leading pair CLZ finds): shifts, compares and
// subtracts only.
constexpr std::uint32_t isqrt32(std::uint32_t x) {
  if (x == 0) return 0;
  std::uint32_t result = 0, bit = std::uint32_t(1) << ((31 - __builtin_clz(x)) & ~1);
  for (; bit != 0; bit >>= 2) {
    if (x >= result + bit) {
      x -= result + bit;
      result = (result >> 1) + bit;
    } else {
      result >>= 1;
    }
  }
  return result;
}

// floor(sqrt(n)) of a 128-bit integer by Newton iteration from a seed at or
// above the root: from any such seed Newton descends monotonically to
// floor(sqrt(n)) and stops there, so the seed changes the number of steps,
// never the result. The seed is (isqrt32(top) + 1) 2^k for top = n / 4^k,
// the leading 31 or 32 bits: (isqrt32(top) + 1)^2 4^k > (top + 1) 4^k > n.
// It is good to about 15 bits, so two or three 128-bit divisions follow
// where a power-of-two seed (good to one bit) took five or six.
constexpr UInt128 isqrt(UInt128 n) {
  if (n == 0) return 0;
  const int half = bitLength(n) > 32 ? (bitLength(n) - 31) / 2 : 0;  // k: top = n / 4^k < 2^32
  UInt128 r = static_cast<UInt128>(isqrt32(static_cast<std::uint32_t>(n >> (2 * half))) + 1) << half;
  while (true) {
    UInt128 next = (r + n / r) >> 1;
    if (next >= r) break;
    r = next;
  }
  return r;
}

// Square root: sqrt(raw * 2^F) is the raw result, rounded to nearest.
// Negative input gives 0, like a clamped discriminant.
template <int F>
constexpr Fixed<F> sqrt(Fixed<F> x) {
  if (x.raw() <= 0) return Fixed<F>();
  UInt128 n = static_cast<UInt128>(x.raw()) << F;
  UInt128 r = isqrt(n);
  if ((r + 1) * (r + 1) - n <= n - r * r) ++r;
  return Fixed<F>::fromRaw(static_cast<typename Fixed<F>::Raw>(r));
}

// The renderer's scalar helpers treat a saturated value as IEEE treats an
// infinity: it is "not finite".
template <int F>
constexpr bool isfinite(Fixed<F> x) {
  return !x.saturated();
}

// Round to nearest integer (halves away from zero), like std::round.
template <int F>
constexpr Fixed<F> round(Fixed<F> x) {
  using Raw = typename Fixed<F>::Raw;
  const Raw half = Raw(1) << (F - 1);
  const Raw mask = ~((Raw(1) << F) - 1);
  const Raw r = x.raw();
  return Fixed<F>::fromRaw(r >= 0 ? ((r + half) & mask) : -((-r + half) & mask));
}

// A compile-time constant: Fixed(double) folded by the compiler, so a
// literal such as 0.5 never costs a floating-point conversion at run time.
template <int F>
consteval Fixed<F> fixedConstant(double v) {
  return Fixed<F>(v);
}

}  // namespace lattice

namespace std {
template <int F>
class numeric_limits<lattice::Fixed<F>> {
 public:
  using T = lattice::Fixed<F>;
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = true;
  static constexpr bool has_infinity = false;  // infinity() saturates instead
  static constexpr bool is_iec559 = false;
  static constexpr int digits = 63;
  static constexpr T max() { return T::fromRaw(T::kMaxRaw); }
  static constexpr T lowest() { return T::fromRaw(T::kMinRaw); }
  static constexpr T min() { return T::fromRaw(1); }
  static constexpr T epsilon() { return T::fromRaw(1); }
  static constexpr T infinity() { return max(); }
};
}  // namespace std
