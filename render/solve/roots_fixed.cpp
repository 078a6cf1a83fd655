// Polynomial roots in fixed point. Closed forms do not survive Q31.32: a
// quartic's resolvent multiplies three coefficients, and coefficients of one
// ray's polynomial span many orders of magnitude (a torus seen from afar:
// c4 = 1, c0 ~ 1e3). So, per call:
//  1. Rescale exactly by powers of two (shifts): x = 2^k y with k chosen so
//     |c_0| ~ |c_n 2^(nk)|, and every coefficient shifted so the largest is
//     just under 2^56 as an integer D_i. Roots of a balanced polynomial
//     cluster around |y| = 1.
//  2. Split the line at |y| = 1: roots with |y| <= 1 are roots of
//     P(y) = sum D_i y^i on [-1, 1]; the others are 1/z for roots z in
//     (-1, 1) of the reversed polynomial R(z) = sum D_i z^(n-i). Both are then
//     evaluated only for arguments in [-1, 1] (Q60 integers), where Horner's
//     intermediates stay below sum |D_i| < 2^61 and every product fits 128 bits.
//  3. Isolate: the roots of P' (found the same way, recursively) cut [-1, 1]
//     into pieces where P is monotone; a piece whose ends differ in sign holds
//     one root, found by safeguarded Newton (bisection when Newton leaves the
//     bracket or stalls), i.e. bracket and polish.
//  4. Map back: x = 2^k y or 2^k / z, rounded to Q31.32, saturated.
#include "render/solve/roots_fixed.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

#include "foundation/rounding.hpp"

namespace lattice::fixed_roots {
namespace {

using Raw = std::int64_t;
constexpr int kQ = 60;  // fraction bits of y and z
constexpr Raw kOneQ = Raw(1) << kQ;
constexpr int kTopBit = 55;  // the largest |D_i| is in [2^55, 2^56)

int topBit(Raw v) {  // floor(log2 |v|), v != 0
  const std::uint64_t u = static_cast<std::uint64_t>(v < 0 ? -v : v);
  return 63 - __builtin_clzll(u);
}

Int128 roundShiftRight(Int128 v, int s) {  // v / 2^s rounded to nearest, s >= 1
  if (s >= 127) return 0;
  const Int128 half = static_cast<Int128>(1) << (s - 1);
  return v >= 0 ? (v + half) >> s : -((-v + half) >> s);
}

// v * 2^s as a 64-bit integer; only called where the result fits.
Raw scaleByPowerOfTwo(Raw v, int s) {
  if (s >= 0) return static_cast<Raw>(static_cast<Int128>(v) << s);
  return static_cast<Raw>(roundShiftRight(v, -s));
}

// y * 2^s saturated to the Q31.32 raw range.
Raw saturatingShift(Int128 y, int s) {
  constexpr Raw kMax = Fixed32::kMaxRaw;
  if (y == 0) return 0;
  if (s < 0) {
    const Int128 r = roundShiftRight(y, -s);
    return r > kMax ? kMax : r < -kMax ? -kMax : static_cast<Raw>(r);
  }
  const Int128 magnitude = y < 0 ? -y : y;
  if (s >= 63 || magnitude > (static_cast<Int128>(kMax) >> s)) return y < 0 ? -kMax : kMax;
  return static_cast<Raw>(y << s);
}

// Horner on [-1, 1]: d[0..n] integers, y in Q60. Each product is rounded once.
Int128 evaluate(const Raw* d, int n, Raw y) {
  Int128 s = d[n];
  for (int k = n - 1; k >= 0; --k) s = roundShiftRight(s * y, kQ) + d[k];
  return s;
}

void derivative(const Raw* d, int n, Raw* out) {
  for (int k = 0; k < n; ++k) out[k] = static_cast<Raw>(k + 1) * d[k + 1];
}

// One root in [lo, hi], P(lo) and P(hi) of opposite signs (lowNegative: P(lo) < 0).
Raw bracketedRoot(const Raw* d, const Raw* dd, int n, Raw lo, Raw hi, bool lowNegative) {
  Raw x = lo + (hi - lo) / 2;
  Raw previousStep = hi - lo;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Int128 v = evaluate(d, n, x);
    if (v == 0) return x;
    if ((v < 0) == lowNegative) lo = x;
    else hi = x;
    if (hi - lo <= 1) break;
    const Int128 slope = evaluate(dd, n - 1, x);
    bool newtonOk = false;
    Raw next = 0;
    if (slope != 0) {
      const Int128 step = (v * kOneQ) / slope;  // |v| < 2^62, so v * 2^60 fits
      const Int128 limit = static_cast<Int128>(previousStep / 2);
      if ((step < 0 ? -step : step) <= limit) {
        next = x - static_cast<Raw>(step);
        newtonOk = next > lo && next < hi;
        // Converged: the step is below 2^-52 of the unit interval.
        if (newtonOk && (step < 0 ? -step : step) <= 256) return next;
      }
    }
    if (!newtonOk) next = lo + (hi - lo) / 2;
    previousStep = next > x ? next - x : x - next;
    x = next;
  }
  const Int128 flo = evaluate(d, n, lo), fhi = evaluate(d, n, hi);
  return (flo < 0 ? -flo : flo) <= (fhi < 0 ? -fhi : fhi) ? lo : hi;
}

// All roots of d (degree n >= 1, d[n] != 0) in [lo, hi], ascending. Roots
// exactly at lo or hi are included.
int isolate(const Raw* d, int n, Raw lo, Raw hi, Raw* out) {
  if (n == 1) {
    // -d0 / d1 in Q60, if it lies in [lo, hi] (|d0| < 2^62, so d0 * 2^60 fits).
    const Int128 num = -static_cast<Int128>(d[0]) * kOneQ;
    const Int128 q = num / d[1];
    if (q < lo || q > hi) return 0;
    out[0] = static_cast<Raw>(q);
    return 1;
  }
  std::array<Raw, 4> dd{};
  derivative(d, n, dd.data());
  std::array<Raw, 3> critical{};
  const int criticalCount = isolate(dd.data(), n - 1, lo, hi, critical.data());

  std::array<Raw, 5> points{};
  std::array<Int128, 5> values{};
  int count = 0;
  points[count++] = lo;
  for (int i = 0; i < criticalCount; ++i)
    if (critical[i] > points[count - 1] && critical[i] < hi) points[count++] = critical[i];
  points[count++] = hi;
  for (int i = 0; i < count; ++i) values[i] = evaluate(d, n, points[i]);

  // A critical point is a (multiple) root when P is zero there within the
  // evaluation's rounding (a few units) and does not change sign around it.
  const Int128 tolerance = 4 * (n + 1);
  auto signChange = [&](int i, int j) { return values[i] != 0 && values[j] != 0 && (values[i] < 0) != (values[j] < 0); };
  std::array<bool, 5> isRoot{};
  isRoot[0] = values[0] == 0;
  isRoot[count - 1] = values[count - 1] == 0;
  for (int i = 1; i + 1 < count; ++i) {
    const Int128 a = values[i] < 0 ? -values[i] : values[i];
    isRoot[i] = a == 0 || (a <= tolerance && !signChange(i - 1, i) && !signChange(i, i + 1));
  }
  int found = 0;
  for (int i = 0; i < count; ++i) {
    if (isRoot[i] && found < n) out[found++] = points[i];
    if (i + 1 == count || isRoot[i] || isRoot[i + 1] || !signChange(i, i + 1)) continue;
    if (found < n) out[found++] = bracketedRoot(d, dd.data(), n, points[i], points[i + 1], values[i] < 0);
  }
  return found;
}

}  // namespace

int solve(const Fixed32* c, int size, Fixed32 roots[4]) {
  int high = -1, low = -1;
  for (int k = 0; k < size; ++k)
    if (c[k].raw() != 0) {
      high = k;
      if (low < 0) low = k;
    }
  if (high <= 0) return 0;  // zero polynomial or a non-zero constant
  bool zeroRoot = low > 0;
  const int n = high - low;
  std::array<Raw, 4> xs{};
  int count = 0;
  if (n > 0) {
    // 1. x = 2^k y balances the end coefficients (k rounded to nearest).
    const int diff = topBit(c[low].raw()) - topBit(c[high].raw());
    const int k = roundedQuotient(diff, n);
    int largest = -1000;
    for (int i = 0; i <= n; ++i)
      if (c[low + i].raw() != 0) largest = std::max(largest, topBit(c[low + i].raw()) + i * k);
    std::array<Raw, 5> d{};
    for (int i = 0; i <= n; ++i) {
      const Raw v = c[low + i].raw();
      const int shift = i * k - largest + kTopBit;
      d[i] = v == 0 || shift < -64 ? 0 : scaleByPowerOfTwo(v, shift);
    }
    // Coefficients more than 2^56 below the largest round to zero; at the
    // ends that lowers the degree (a root beyond reach) or leaves a root at y = 0.
    int top = n, bottom = 0;
    while (top > 0 && d[top] == 0) --top;
    while (bottom < top && d[bottom] == 0) ++bottom;
    if (bottom > 0) zeroRoot = true;
    const int m = top - bottom;
    if (m > 0) {
      std::array<Raw, 5> p{}, r{};
      for (int i = 0; i <= m; ++i) {
        p[i] = d[bottom + i];
        r[i] = d[top - i];
      }
      // 2-3. |y| <= 1 from P, |y| > 1 from R(z), z = 1/y in (-1, 1).
      // Degree 1 (a plane's ray): the root -D0/D1 lies in [-1, 1] only if
      // |D0| <= |D1|, for |D1| < 2^56 makes the quotient of a larger |D0|
      // more than 2^60 + 16 in Q60, which isolate() would refuse; so the side
      // that cannot hold it is skipped with its 128-bit division, and only
      // |D0| = |D1| asks both, as before.
      std::array<Raw, 4> ys{}, zs{};
      const bool onlyP = m == 1 && std::abs(p[0]) < std::abs(p[1]), onlyR = m == 1 && std::abs(p[1]) < std::abs(p[0]);
      const int ny = onlyR ? 0 : isolate(p.data(), m, -kOneQ, kOneQ, ys.data());
      const int nz = onlyP ? 0 : isolate(r.data(), m, -kOneQ, kOneQ, zs.data());
      // 4. Back to Q31.32: x = y 2^k, or 2^k / z.
      for (int i = 0; i < nz && count < 4; ++i) {
        if (zs[i] >= 0 || zs[i] <= -kOneQ) continue;  // the negative ones first (ascending x)
        const int e = k + 32 + kQ;
        xs[count++] = e >= 126 ? -Fixed32::kMaxRaw
                      : e <= 0 ? 0
                               : saturatingShift((static_cast<Int128>(1) << e) / zs[i], 0);
      }
      for (int i = 0; i < ny && count < 4; ++i) xs[count++] = saturatingShift(ys[i], k + 32 - kQ);
      for (int i = nz - 1; i >= 0 && count < 4; --i) {
        if (zs[i] <= 0 || zs[i] >= kOneQ) continue;
        const int e = k + 32 + kQ;
        xs[count++] = e >= 126 ? Fixed32::kMaxRaw
                      : e <= 0 ? 0
                               : saturatingShift((static_cast<Int128>(1) << e) / zs[i], 0);
      }
    }
  }
  if (zeroRoot && count < 4) xs[count++] = 0;
  std::sort(xs.begin(), xs.begin() + count);
  int unique = 0;
  for (int i = 0; i < count; ++i)
    if (unique == 0 || xs[i] != roots[unique - 1].raw()) roots[unique++] = Fixed32::fromRaw(xs[i]);
  return unique;
}

Fixed32 evaluate(std::span<const Fixed32> c, Fixed32 x) {
  if (c.empty()) return Fixed32();
  constexpr Int128 kHuge = static_cast<Int128>(1) << 100;  // far beyond the Q31.32 range, far below 2^127
  const Raw xr = x.raw();
  const int xBits = xr == 0 ? 0 : topBit(xr) + 1;
  Int128 s = c.back().raw();
  for (std::size_t k = c.size() - 1; k-- > 0;) {
    // |s| <= 2^100 and |x| < 2^63: the product fits unless s is already huge
    // and |x| >= 2^27, in which case the result is huge as well.
    const int sBits = bitLength(static_cast<UInt128>(s < 0 ? -s : s));
    if (sBits + xBits > 126) s = ((s < 0) != (xr < 0)) ? -kHuge : kHuge;
    else s = roundShiftRight(s * xr, 32);
    s += c[k].raw();
    if (s > kHuge) s = kHuge;
    if (s < -kHuge) s = -kHuge;
  }
  return Fixed32::fromRaw(s > Fixed32::kMaxRaw ? Fixed32::kMaxRaw : s < -Fixed32::kMaxRaw ? -Fixed32::kMaxRaw : static_cast<Raw>(s));
}

}  // namespace lattice::fixed_roots
