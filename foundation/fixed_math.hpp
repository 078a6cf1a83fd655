#pragma once
// The transcendental functions the per-pixel path needs in fixed point, in
// integer arithmetic only: the Phong term (r . s)^n_spec of eq. 2.3 is
// pow(x, n) = 2^(n log2 x) with log2 by repeated squaring (one result bit per
// squaring) and 2^f by a product of constants 2^(2^-i), themselves made at
// compile time by repeated integer square roots of 2.
#include <array>

#include "foundation/fixed.hpp"

namespace lattice {

namespace fixed_detail {

// 2^(2^-i) in Q62 for i = 1..40 (index 0 unused): t_1 = sqrt(2), t_(i+1) = sqrt(t_i).
constexpr std::array<UInt128, 41> makeRootsOfTwo() {
  std::array<UInt128, 41> t{};
  UInt128 v = static_cast<UInt128>(2) << 62;
  for (int i = 1; i <= 40; ++i) {
    v = isqrt(v << 62);  // sqrt of a Q62 value, still Q62
    t[static_cast<std::size_t>(i)] = v;
  }
  return t;
}
inline constexpr std::array<UInt128, 41> kRootsOfTwo = makeRootsOfTwo();

}  // namespace fixed_detail

// log2(x) for x > 0; x <= 0 gives the most negative value (log2 0 = -inf).
template <int F>
constexpr Fixed<F> log2(Fixed<F> x) {
  using Raw = typename Fixed<F>::Raw;
  if (x.raw() <= 0) return std::numeric_limits<Fixed<F>>::lowest();
  const int top = 63 - __builtin_clzll(static_cast<std::uint64_t>(x.raw()));  // the leading one
  // Mantissa in [1, 2) as Q62.
  UInt128 m = top <= 62 ? static_cast<UInt128>(x.raw()) << (62 - top) : static_cast<UInt128>(x.raw()) >> (top - 62);
  Raw fraction = 0;
  for (int bit = F - 1; bit >= 0; --bit) {
    m = (m * m) >> 62;
    if (m >= (static_cast<UInt128>(2) << 62)) {
      m >>= 1;
      fraction |= Raw(1) << bit;
    }
  }
  return Fixed<F>::fromRaw((static_cast<Raw>(top - F) << F) + fraction);
}

// 2^y; saturates above the range and flushes to 0 below the resolution.
template <int F>
constexpr Fixed<F> exp2(Fixed<F> y) {
  using Raw = typename Fixed<F>::Raw;
  const Raw integer = y.raw() >> F;  // floor
  const Raw fraction = y.raw() - (integer << F);
  if (integer > 62 - F) return std::numeric_limits<Fixed<F>>::max();
  if (integer < -F - 1) return Fixed<F>();
  UInt128 m = static_cast<UInt128>(1) << 62;  // 1.0 in Q62
  for (int bit = F - 1, i = 1; bit >= 0 && i <= 40; --bit, ++i)
    if ((fraction >> bit) & 1) m = (m * fixed_detail::kRootsOfTwo[static_cast<std::size_t>(i)]) >> 62;
  // m in [1, 2) as Q62: the result's raw value is m * 2^(integer + F - 62), rounded.
  const int shift = 62 - F - static_cast<int>(integer);  // >= 0
  const UInt128 rounded = shift == 0 ? m : (m + (static_cast<UInt128>(1) << (shift - 1))) >> shift;
  const UInt128 limit = static_cast<UInt128>(Fixed<F>::kMaxRaw);
  return Fixed<F>::fromRaw(static_cast<Raw>(rounded > limit ? limit : rounded));
}

// x^y for x >= 0 (negative x gives 0: the renderer only raises clamped cosines).
template <int F>
constexpr Fixed<F> pow(Fixed<F> x, Fixed<F> y) {
  if (x.raw() <= 0) return y.raw() == 0 ? Fixed<F>(1) : Fixed<F>();
  if (y.raw() == 0) return Fixed<F>(1);
  return exp2(y * log2(x));
}

}  // namespace lattice
