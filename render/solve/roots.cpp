// Real roots of polynomials of degree <= 4 (contract in render/solve/roots.hpp,
// algorithm and measured error bounds in docs/roots.md).
//
// Every solve goes through the same steps:
//  1. reject NaN/inf, find the effective degree, strip exact zero roots;
//  2. scale exactly by powers of two (x = 2^s y, coefficients times 2^m) so
//     the leading and constant coefficients are of equal size and the largest
//     is near 1: float inputs of 1e30 or 1e-30 then neither overflow nor
//     underflow, and every later step sees a "balanced" polynomial;
//  3. closed form: stable quadratic, cubic by Cardano/trigonometric start +
//     deflation, quartic by a Ferrari factorisation into two quadratics that
//     is refined until its backward error stops shrinking (the approach of
//     Orellana & De Michele, ACM TOMS Algorithm 1010, 2020);
//  4. Newton polishing of every root on the (scaled) original polynomial,
//     evaluated with a compensated Horner scheme (Graillat, Langlois & Louvet
//     2005) so the residual is nearly exact;
//  5. a check: every root must have a backward error of a few ulps; if not,
//     or when the coefficients span too many orders of magnitude, the roots
//     are recomputed by isolation (roots of p' split the line into monotone
//     pieces, each bracketed root found by safeguarded Newton/bisection).
// Everything is computed in T: the float path never widens to double.
#include "render/solve/roots.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>

#include <fmt/format.h>

#include "render/solve/roots_fixed.hpp"
#include "foundation/counter.hpp"
#include "foundation/error.hpp"
#include "foundation/rounding.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice::roots_detail {
// How many solves needed the isolation fallback since start-up; read by the
// roots tests and benchmark to report how often it kicks in. Not part of the
// public header on purpose: it is a diagnostic, not an interface.
std::uint64_t fallbackCount() noexcept;
}  // namespace lattice::roots_detail

namespace lattice {
namespace {

Counter fallbackCounter;

template <typename T>
constexpr T kEps = std::numeric_limits<T>::epsilon();

// A root is accepted when its backward error |p(x)| / sum |c_k||x|^k is at
// most this many ulps: p(x) = 0 then holds for coefficients perturbed by a
// few ulps, i.e. x cannot be told apart from a root of the given polynomial.
template <typename T>
constexpr T kRootTolerance = T(16) * kEps<T>;

// The fallback takes over when a polished closed-form root is worse than this.
template <typename T>
constexpr T kVerifyTolerance = T(64) * kEps<T>;

// Balanced coefficients spanning more than this (ratio of the largest to the
// smaller of |c_0|, |c_n|) go straight to isolation: the Ferrari resolvent
// multiplies up to three coefficients, which could then overflow or flush to
// zero. Precision is not the limit: balancing plus polishing keep roots spread
// over 24 decades (double) or 18 (float) at full accuracy (docs/roots.md), and
// a precision loss is caught by the residual checks anyway.
template <typename T>
T spanLimit() {
  return std::ldexp(T(1), std::numeric_limits<T>::max_exponent / 3);
}

// p(x) with a compensated Horner scheme: the rounding error of every step is
// captured exactly (fma for products, TwoSum for sums) and added back, so the
// result is as if computed in twice the precision. `scale` is sum |c_k||x|^k,
// the denominator of the backward error, and `slope` is p'(x) (plain Horner:
// Newton only needs its leading digits).
//
// When p(x) overflows (|x| huge on a polynomial whose coefficients span a wide
// range), all three are returned divided by |x|^n instead, computed from the
// reversed polynomial in y = 1/x: signs, the backward error and the Newton
// step value/slope are unchanged by that common positive factor.
template <typename T>
struct Evaluation {
  T value;
  T scale;
  T slope;
};

template <typename T>
Evaluation<T> hornerCompensated(const T* c, int n, T x) {
  T s = c[n];
  T correction = 0;
  T slope = 0;
  const T ax = std::abs(x);
  T scale = std::abs(c[n]);
  for (int k = n - 1; k >= 0; --k) {
    slope = slope * x + s;
    const T product = s * x;
    const T productError = std::fma(s, x, -product);
    const T sum = product + c[k];
    const T virtualB = sum - product;
    const T sumError = (product - (sum - virtualB)) + (c[k] - virtualB);
    correction = correction * x + (productError + sumError);
    s = sum;
    scale = scale * ax + std::abs(c[k]);
  }
  return {s + correction, scale, slope};
}

template <typename T>
Evaluation<T> evaluateCompensated(const T* c, int n, T x) {
  const Evaluation<T> e = hornerCompensated(c, n, x);
  if ((std::isfinite(e.value) && std::isfinite(e.scale) && std::isfinite(e.slope)) || std::abs(x) <= 1) return e;
  // p(x) / x^n = q(y) with q the reversed polynomial, y = 1/x; and
  // p'(x) / x^n = y r(y) with r(y) = sum k c_k y^(n-k).
  std::array<T, 5> reversed{};
  for (int k = 0; k <= n; ++k) reversed[k] = c[n - k];
  const T y = T(1) / x;
  const Evaluation<T> q = hornerCompensated(reversed.data(), n, y);
  T r = 0;
  for (int k = 0; k <= n; ++k) r = r * y + T(k) * c[k];
  const T sign = (n % 2 == 1 && x < 0) ? T(-1) : T(1);  // x^n / |x|^n
  return {sign * q.value, q.scale, sign * y * r};
}
template <typename T>
T backwardError(const Evaluation<T>& e) {
  return e.scale > 0 ? std::abs(e.value) / e.scale : T(0);
}

// p'(x) by plain Horner: Newton only needs its leading digits.
template <typename T>
T derivative(const T* c, int n, T x) {
  T d = T(n) * c[n];
  for (int k = n - 1; k >= 1; --k) d = d * x + T(k) * c[k];
  return d;
}

template <typename T>
T secondDerivative(const T* c, int n, T x) {
  if (n < 2) return 0;
  T d = T(n * (n - 1)) * c[n];
  for (int k = n - 1; k >= 2; --k) d = d * x + T(k * (k - 1)) * c[k];
  return d;
}

// Newton on p from a close start. A step is kept only if it lowers |p|, so
// polishing can never make a root worse (multiple roots, where p' vanishes,
// simply stop early).
template <typename T>
struct Polished {
  T x;
  T backward;
};

template <typename T>
Polished<T> polish(const T* c, int n, T x) {
  Evaluation<T> e = evaluateCompensated(c, n, x);
  for (int iteration = 0; iteration < 8 && e.value != 0; ++iteration) {
    const T d = e.slope;
    if (d == 0 || !std::isfinite(d)) break;
    const T step = e.value / d;
    const T next = x - step;
    if (!std::isfinite(next) || next == x) break;
    const Evaluation<T> f = evaluateCompensated(c, n, next);
    if (!(std::abs(f.value) < std::abs(e.value))) break;
    x = next;
    e = f;
    if (std::abs(step) <= kEps<T> * std::abs(x)) break;
  }
  return {x, backwardError(e)};
}

// A closed-form step produced a complex pair re +- i im. When im is tiny the
// pair may be a double (or higher) real root split by rounding: the minimum
// of |p| near re is a root of p', so Newton on p' locates it, and it is a
// root if p is within rounding there.
template <typename T>
bool nearRealRoot(const T* c, int n, T re, T& root) {
  T x = re;
  for (int iteration = 0; iteration < 6; ++iteration) {
    const T d1 = derivative(c, n, x);
    const T d2 = secondDerivative(c, n, x);
    if (d1 == 0 || d2 == 0 || !std::isfinite(d1 / d2)) break;
    const T next = x - d1 / d2;
    if (!std::isfinite(next) || next == x) break;
    if (std::abs(next - re) > T(0.5) * (std::abs(re) + T(1))) break;  // wandered off
    x = next;
  }
  if (backwardError(evaluateCompensated(c, n, x)) <= kRootTolerance<T>) {
    root = x;
    return true;
  }
  if (backwardError(evaluateCompensated(c, n, re)) <= kRootTolerance<T>) {
    root = re;
    return true;
  }
  return false;
}

// --- Stable quadratic ----------------------------------------------------

// a x^2 + b x + c, a != 0. Kahan's discriminant: b^2 and 4ac are formed with
// their rounding errors (fma), so near-double roots do not lose half their
// digits to cancellation; q = -(b + sign(b) sqrt(disc)) / 2 avoids the
// cancellation of the textbook formula, and the second root is c / q.
// Returns 2 roots, 1 (a double root, reported once) or 0 with the complex
// pair's real part and imaginary part in re/im.
template <typename T>
int quadraticCore(T a, T b, T c, T roots[2], T& re, T& im) {
  const T bb = b * b;
  const T bbError = std::fma(b, b, -bb);
  const T fourA = T(4) * a;
  const T ac4 = fourA * c;
  const T ac4Error = std::fma(fourA, c, -ac4);
  const T disc = (bb - ac4) + (bbError - ac4Error);
  // Computed this way the discriminant is wrong by at most a few ulps of
  // itself plus O(eps^2) of b^2: anything smaller is zero. (A pair split off
  // the real axis by rounding in the coefficients is caught by nearRealRoot.)
  const T noise = T(4) * kEps<T> * kEps<T> * (bb + std::abs(ac4));
  if (disc < -noise) {
    re = -b / (T(2) * a);
    im = std::sqrt(-disc) / (T(2) * std::abs(a));
    return 0;
  }
  if (disc <= noise) {
    roots[0] = -b / (T(2) * a);
    return 1;
  }
  const T q = T(-0.5) * (b + std::copysign(std::sqrt(disc), b));
  const T r1 = q / a;
  const T r2 = c / q;
  roots[0] = std::min(r1, r2);
  roots[1] = std::max(r1, r2);
  return 2;
}

// At most four values: insertion sort (std::sort here also trips GCC 12's
// -Warray-bounds false positive at -O3).
template <typename T>
void sortSmall(T* x, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && x[j] < x[j - 1]; --j) std::swap(x[j], x[j - 1]);
}

// --- Isolation fallback ----------------------------------------------------

// Where to split a bracket when Newton is not used: geometrically while the
// ends differ by more than a factor 4 (zero counts as the smallest
// subnormal), so a root of any magnitude is reached in about log2(exponent
// range) + mantissa bits steps; at zero first when the bracket contains it.
template <typename T>
T splitPoint(T lo, T hi) {
  if (lo < 0 && hi > 0) return 0;
  const T tiny = std::numeric_limits<T>::denorm_min();
  if (lo >= 0) {
    const T l = std::max(lo, tiny);
    if (hi > 4 * l) return std::sqrt(l) * std::sqrt(hi);
  } else {
    const T h = std::max(-hi, tiny);
    if (-lo > 4 * h) return -(std::sqrt(h) * std::sqrt(-lo));
  }
  return lo / 2 + hi / 2;  // no overflow even for +-max
}

// Safeguarded Newton inside a bracket [lo, hi] with p(lo), p(hi) of opposite
// signs: a Newton step is taken when it stays inside the bracket and at least
// halves the previous step, otherwise the bracket is split. Always converges.
template <typename T>
T bracketedRoot(const T* c, int n, T lo, T hi, bool lowIsNegative) {
  T x = splitPoint(lo, hi);
  T previousStep = std::numeric_limits<T>::infinity();
  for (int iteration = 0; iteration < 400; ++iteration) {
    const Evaluation<T> e = evaluateCompensated(c, n, x);
    if (e.value == 0) return x;
    if ((e.value < 0) == lowIsNegative) lo = x;
    else hi = x;
    T next = x - e.value / e.slope;
    const bool newtonOk = e.slope != 0 && next > lo && next < hi &&
                          std::abs(next - x) <= T(0.5) * previousStep;
    if (!newtonOk) next = splitPoint(lo, hi);
    previousStep = std::abs(next - x);
    if (!(next > lo && next < hi)) break;  // no representable point left inside
    x = next;
  }
  const T flo = std::abs(evaluateCompensated(c, n, lo).value);
  const T fhi = std::abs(evaluateCompensated(c, n, hi).value);
  return flo <= fhi ? lo : hi;
}

// All real roots of c (degree n >= 1, c[n] != 0), ascending, without any
// closed form: the roots of p' (found the same way, recursively) split the
// line into pieces on which p is monotone, so each piece holds at most one
// root, found by bracketing. A critical point where p is zero within rounding
// is a multiple root.
template <typename T>
int isolateRoots(const T* c, int n, T* out) {
  if (n == 1) {
    const T x = -c[0] / c[1];
    if (!std::isfinite(x)) return 0;
    out[0] = x;
    return 1;
  }
  std::array<T, 4> dc{};
  for (int k = 0; k < n; ++k) dc[k] = T(k + 1) * c[k + 1];
  std::array<T, 3> critical{};
  const int criticalCount = isolateRoots(dc.data(), n - 1, critical.data());

  // Fujiwara's bound: every root has |x| < 2 max |c_{n-k} / c_n|^(1/k).
  T bound = 0;
  for (int k = 1; k <= n; ++k) {
    T ratio = std::abs(c[n - k] / c[n]);
    if (k == n) ratio /= 2;
    bound = std::max(bound, std::pow(ratio, T(1) / T(k)));
  }
  bound = T(2.5) * bound + std::numeric_limits<T>::min();
  if (!std::isfinite(bound)) bound = std::numeric_limits<T>::max();

  std::array<T, 5> points{};
  std::array<T, 5> values{};
  std::array<T, 5> backward{};
  std::array<bool, 5> isRoot{};
  int pointCount = 0;
  points[pointCount++] = -bound;
  for (int i = 0; i < criticalCount; ++i) {
    if (critical[i] > -bound && critical[i] < bound &&
        (pointCount == 1 || critical[i] > points[pointCount - 1])) {
      points[pointCount++] = critical[i];
    }
  }
  points[pointCount++] = bound;
  for (int i = 0; i < pointCount; ++i) {
    const Evaluation<T> e = evaluateCompensated(c, n, points[i]);
    values[i] = e.value;
    backward[i] = backwardError(e);
  }
  // The compensated values have reliable signs, so a sign change always wins:
  // two close simple roots stay two. A critical point is a (multiple) root
  // when p is exactly zero there, or when p touches zero within rounding
  // without changing sign on either side.
  auto signChange = [&values](int i, int j) {
    return values[i] != 0 && values[j] != 0 && (values[i] < 0) != (values[j] < 0);
  };
  for (int i = 1; i + 1 < pointCount; ++i) {
    isRoot[i] = values[i] == 0 ||
                (backward[i] <= kRootTolerance<T> && !signChange(i - 1, i) && !signChange(i, i + 1));
  }

  int count = 0;
  for (int i = 0; i + 1 < pointCount; ++i) {
    if (isRoot[i]) out[count++] = points[i];
    if (isRoot[i] || isRoot[i + 1]) continue;  // monotone piece touches a root: no other
    const bool lowNegative = values[i] < 0;
    if (values[i] == 0 || values[i + 1] == 0 || lowNegative == (values[i + 1] < 0)) continue;
    if (count < n) out[count++] = bracketedRoot(c, n, points[i], points[i + 1], lowNegative);
  }
  return count;
}

// --- Closed forms on balanced polynomials ----------------------------------

// Collects roots found by a closed form, polishes them on the original
// polynomial and records whether all of them passed the residual check.
template <typename T>
struct RootSet {
  std::array<T, 4> x{};
  int count = 0;
  bool trustworthy = true;

  T add(const T* c, int n, T start) {
    if (!std::isfinite(start)) {
      trustworthy = false;
      return start;
    }
    const Polished<T> p = polish(c, n, start);
    if (!(p.backward <= kVerifyTolerance<T>)) trustworthy = false;
    if (count < 4) x[count++] = p.x;
    return p.x;
  }
};

template <typename T>
void addQuadraticFactor(const T* c, int n, T a, T b, T q, RootSet<T>& set) {
  T r[2];
  T re = 0;
  T im = 0;
  const int k = quadraticCore(a, b, q, r, re, im);
  for (int i = 0; i < k; ++i) set.add(c, n, r[i]);
  if (k == 0 && std::isfinite(re) && im <= T(0.25) * std::abs(re) + T(0.01)) {
    T root;
    if (nearRealRoot(c, n, re, root)) set.add(c, n, root);
  }
}

// A real root of the monic cubic x^3 + a x^2 + b x + d from the closed form
// on its depressed form t^3 + p t + q (x = t - a/3): Cardano when there is
// one real root (the cube root taken of the sum without cancellation), the
// trigonometric form when there are three. `largest` picks the largest of
// three, otherwise the one farthest from the origin (the best to deflate by).
template <typename T>
T cubicStart(T a, T b, T d, bool largest) {
  const T shift = a / T(3);
  const T p = b - a * shift;
  const T q = d - shift * (b - T(2) * shift * shift);
  const T halfQ = q / T(2);
  const T thirdP = p / T(3);
  const T disc = halfQ * halfQ + thirdP * thirdP * thirdP;
  T t;
  if (disc > 0) {
    const T big = -std::copysign(std::cbrt(std::abs(halfQ) + std::sqrt(disc)), q);
    t = big != 0 ? big - thirdP / big : T(0);
  } else {
    const T m = T(2) * std::sqrt(-thirdP);
    const T cosine = m != 0 ? std::clamp(T(3) * q / (p * m), T(-1), T(1)) : T(0);
    const T theta = std::acos(cosine) / T(3);
    const T t0 = m * std::cos(theta);  // the largest of the three
    if (largest) {
      t = t0;
    } else {
      const T t2 = m * std::cos(theta + T(2) * std::numbers::pi_v<T> / T(3));  // the smallest
      t = std::abs(t0 - shift) >= std::abs(t2 - shift) ? t0 : t2;
    }
  }
  return t - shift;
}

// Cubic: one real root from the closed form, the largest in magnitude,
// polished; the cubic is then deflated to a quadratic, choosing forward or
// backward deflation by whichever reproduces the unused coefficient better.
template <typename T>
void solveCubicBalanced(const T* c, RootSet<T>& set) {
  const T a = c[2] / c[3];
  const T b = c[1] / c[3];
  const T d = c[0] / c[3];
  const T first = set.add(c, 3, cubicStart(a, b, d, false));
  if (!std::isfinite(first) || first == 0) {
    set.trustworthy = false;
    return;
  }
  // Monic x^3 + a x^2 + b x + d = (x - r)(x^2 + B x + C).
  const T forwardB = a + first;
  const T forwardC = b + first * forwardB;
  const T backwardC = -d / first;
  const T backwardB = (backwardC - b) / first;
  const T forwardMiss = std::abs(first * forwardC + d) /
                        (std::abs(d) + std::abs(first * forwardC) + std::numeric_limits<T>::min());
  const T backwardMiss = std::abs(backwardB - first - a) /
                         (std::abs(a) + std::abs(first) + std::abs(backwardB) + std::numeric_limits<T>::min());
  if (forwardMiss <= backwardMiss) addQuadraticFactor(c, 3, T(1), forwardB, forwardC, set);
  else addQuadraticFactor(c, 3, T(1), backwardB, backwardC, set);
}

// x^4 + a x^3 + b x^2 + c x + d = (x^2 + al1 x + be1)(x^2 + al2 x + be2).
template <typename T>
struct Factorisation {
  T al1, be1, al2, be2;
};

// Componentwise backward error of a factorisation: how far the product's
// coefficients are from a, b, c, d relative to the size of their terms.
template <typename T>
T factorisationError(const Factorisation<T>& f, T a, T b, T c, T d) {
  const T tiny = std::numeric_limits<T>::min();
  const T e1 = std::abs(f.al1 + f.al2 - a) / (std::abs(f.al1) + std::abs(f.al2) + std::abs(a) + tiny);
  const T e2 = std::abs(f.be1 + f.be2 + f.al1 * f.al2 - b) /
               (std::abs(f.be1) + std::abs(f.be2) + std::abs(f.al1 * f.al2) + std::abs(b) + tiny);
  const T e3 = std::abs(f.al1 * f.be2 + f.al2 * f.be1 - c) /
               (std::abs(f.al1 * f.be2) + std::abs(f.al2 * f.be1) + std::abs(c) + tiny);
  const T e4 = std::abs(f.be1 * f.be2 - d) / (std::abs(f.be1 * f.be2) + std::abs(d) + tiny);
  return std::max(std::max(e1, e2), std::max(e3, e4));
}

// One Newton step on the four equations linking the factorisation to the
// quartic's coefficients (4x4 Jacobian, Gaussian elimination with partial
// pivoting). Returns false when the Jacobian is singular, i.e. when the two
// factors share a root.
template <typename T>
bool refineStep(Factorisation<T>& f, T a, T b, T c, T d) {
  // Unknowns: al1, be1, al2, be2.
  T m[4][5] = {
      {1, 0, 1, 0, -(f.al1 + f.al2 - a)},
      {f.al2, 1, f.al1, 1, -(f.be1 + f.be2 + f.al1 * f.al2 - b)},
      {f.be2, f.al2, f.be1, f.al1, -(f.al1 * f.be2 + f.al2 * f.be1 - c)},
      {0, f.be2, 0, f.be1, -(f.be1 * f.be2 - d)},
  };
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
    if (m[pivot][col] == 0) return false;
    if (pivot != col)
      for (int k = 0; k < 5; ++k) std::swap(m[pivot][k], m[col][k]);
    for (int r = col + 1; r < 4; ++r) {
      const T factor = m[r][col] / m[col][col];
      for (int k = col; k < 5; ++k) m[r][k] -= factor * m[col][k];
    }
  }
  T delta[4];
  for (int r = 3; r >= 0; --r) {
    T s = m[r][4];
    for (int k = r + 1; k < 4; ++k) s -= m[r][k] * delta[k];
    delta[r] = s / m[r][r];
  }
  f.al1 += delta[0];
  f.be1 += delta[1];
  f.al2 += delta[2];
  f.be2 += delta[3];
  return std::isfinite(f.al1) && std::isfinite(f.be1) && std::isfinite(f.al2) && std::isfinite(f.be2);
}

// Builds the factorisation from the resolvent root, using for each pair
// (al1, al2), (be1, be2) the form without cancellation for the larger member
// and the product relation (be1 be2 = d) for the smaller, then refines it
// while its backward error keeps shrinking.
template <typename T>
Factorisation<T> factorFromResolvent(T a, T b, T c, T d, T sqrtA, T offset, T phi, T& error) {
  Factorisation<T> f{};
  const T halfA = a / T(2);
  const T halfPhi = phi / T(2);
  f.al1 = halfA - sqrtA;
  f.al2 = halfA + sqrtA;
  f.be1 = halfPhi - offset;
  f.be2 = halfPhi + offset;
  if (std::abs(f.be1) > std::abs(f.be2)) {
    if (f.be1 != 0) f.be2 = d / f.be1;
  } else if (f.be2 != 0) {
    f.be1 = d / f.be2;
  }
  error = factorisationError(f, a, b, c, d);
  // Refinement stops at 2 ulps of backward error: below that the rounding of
  // the residual itself decides whether a step "improves".
  for (int iteration = 0; iteration < 8 && error > T(2) * kEps<T>; ++iteration) {
    Factorisation<T> next = f;
    if (!refineStep(next, a, b, c, d)) break;
    const T nextError = factorisationError(next, a, b, c, d);
    if (!(nextError < error)) break;
    f = next;
    error = nextError;
  }
  return f;
}

template <typename T>
int solveCubicInternal(const T* c, T* roots);

template <typename T>
void solveQuarticBalanced(const T* c, RootSet<T>& set) {
  const T a = c[3] / c[4];
  const T b = c[2] / c[4];
  const T cc = c[1] / c[4];
  const T d = c[0] / c[4];
  // Ferrari: x^4 + ... = (x^2 + a x/2 + phi/2)^2 - (A x^2 + B x + C) with
  // A = a^2/4 - b + phi, B = a phi/2 - c, C = phi^2/4 - d; the bracket is a
  // perfect square when phi is a root of this resolvent cubic. Its largest
  // root makes A, C >= 0, so both factors are real.
  const T resolvent[4] = {-(cc * cc + a * a * d - T(4) * b * d), a * cc - T(4) * d, -b, T(1)};
  // Only its largest root is needed: closed form, then Newton on the
  // resolvent; the factorisation's own refinement and backward-error check
  // below catch a poor phi.
  const Polished<T> polishedPhi = polish(resolvent, 3, cubicStart(resolvent[2], resolvent[1], resolvent[0], true));
  T phi = polishedPhi.x;
  if (!std::isfinite(phi)) {
    // Resolvent coefficients out of range for the closed form: solve it fully.
    T phis[3];
    const int phiCount = solveCubicInternal(resolvent, phis);
    if (phiCount == 0) {
      set.trustworthy = false;
      return;
    }
    phi = phis[phiCount - 1];
  }
  const T bigA = std::max(a * a / T(4) - b + phi, T(0));
  const T bigB = a * phi / T(2) - cc;
  const T bigC = std::max(phi * phi / T(4) - d, T(0));
  const T sqrtA = std::sqrt(bigA);
  // Two ways to get the constant offset of the square root of A x^2 + B x + C:
  // B / (2 sqrt A) is best when A is large, sign(B) sqrt C when A is small.
  T bestError = std::numeric_limits<T>::infinity();
  Factorisation<T> best{};
  {
    T error;
    const Factorisation<T> f =
        factorFromResolvent(a, b, cc, d, sqrtA, std::copysign(std::sqrt(bigC), bigB), phi, error);
    if (error < bestError) {
      bestError = error;
      best = f;
    }
  }
  if (sqrtA > 0 && bestError > T(2) * kEps<T>) {
    T error;
    const Factorisation<T> f = factorFromResolvent(a, b, cc, d, sqrtA, bigB / (T(2) * sqrtA), phi, error);
    if (error < bestError) {
      bestError = error;
      best = f;
    }
  }
  // A factorisation that could not be refined to a few ulps belongs to a
  // polynomial measurably different from ours; for clustered roots that is
  // enough to turn a real pair complex. Isolation settles it.
  if (!(bestError <= kVerifyTolerance<T>)) {
    set.trustworthy = false;
    return;
  }
  addQuadraticFactor(c, 4, T(1), best.al1, best.be1, set);
  addQuadraticFactor(c, 4, T(1), best.al2, best.be2, set);
}

// --- Preparation and dispatch -----------------------------------------------

// x * 2^e, exactly as std::ldexp rounds it, but without the library call when
// 2^e is a normal number of T (the common case: this runs for every
// coefficient and root of every solve).
template <typename T>
T timesPowerOfTwo(T x, int e) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  constexpr int kMantissaBits = std::numeric_limits<T>::digits - 1;
  constexpr int kBias = std::numeric_limits<T>::max_exponent - 1;
  if (e < 1 - kBias || e > kBias) return std::ldexp(x, e);
  return x * std::bit_cast<T>(static_cast<Bits>(static_cast<Bits>(e + kBias) << kMantissaBits));
}

// The polynomial after exact power-of-two scaling: p(x) = 2^-m P(2^-shift x)
// with P = scaled. `degree` excludes stripped zero roots.
template <typename T>
struct Balanced {
  std::array<T, 5> c{};
  int degree = 0;
  int shift = 0;
  bool zeroRoot = false;
};

// Returns false if there is nothing to solve (invalid or constant input).
template <typename T>
bool balance(const T* c, int size, Balanced<T>& out) {
  int high = -1;
  for (int k = 0; k < size; ++k) {
    if (!std::isfinite(c[k])) return false;
    if (c[k] != 0) high = k;
  }
  if (high <= 0) return false;  // zero polynomial or non-zero constant
  int low = 0;
  while (c[low] == 0) ++low;
  out.zeroRoot = low > 0;
  out.degree = high - low;
  const int n = out.degree;
  if (n == 0) return true;
  const int e0 = std::ilogb(c[low]);
  const int en = std::ilogb(c[high]);
  // x = 2^shift y makes |c_0| and |c_n 2^(n shift)| about equal.
  const int diff = e0 - en;
  out.shift = roundedQuotient(diff, n);
  int maxExponent = std::numeric_limits<int>::min();
  for (int k = 0; k <= n; ++k) {
    if (c[low + k] != 0) maxExponent = std::max(maxExponent, std::ilogb(c[low + k]) + k * out.shift);
  }
  for (int k = 0; k <= n; ++k) out.c[k] = timesPowerOfTwo(c[low + k], k * out.shift - maxExponent);
  // Coefficients more than the whole exponent range below the largest one
  // (only possible when they span over ~2^1000 in double, ~2^250 in float)
  // flush to zero. The end ones then no longer define roots we can return:
  // drop them so the solvers' preconditions (c_0, c_n != 0) hold, i.e. treat
  // them as the negligible terms they have become. docs/roots.md: "Range".
  int top = n;
  while (top > 0 && out.c[top] == 0) --top;
  int bottom = 0;
  while (bottom < top && out.c[bottom] == 0) ++bottom;
  if (bottom > 0) {
    out.zeroRoot = true;
    for (int k = 0; k + bottom <= top; ++k) out.c[k] = out.c[k + bottom];
  }
  out.degree = top - bottom;
  return true;
}

template <typename T>
bool spansTooMuch(const T* c, int n) {
  T largest = 0;
  for (int k = 0; k <= n; ++k) largest = std::max(largest, std::abs(c[k]));
  return largest > spanLimit<T>() * std::min(std::abs(c[0]), std::abs(c[n]));
}

// Roots of a balanced polynomial (c[0], c[n] != 0), ascending, not unscaled.
template <typename T>
int solveBalanced(const T* c, int n, T* roots, bool countFallback) {
  if (n == 1) {
    roots[0] = -c[0] / c[1];
    return 1;
  }
  RootSet<T> set;
  if (n == 2) {
    addQuadraticFactor(c, 2, c[2], c[1], c[0], set);
    // A quadratic's closed form is exact up to a few ulps: no fallback needed.
    sortSmall(set.x.data(), set.count);
    std::copy(set.x.begin(), set.x.begin() + set.count, roots);
    return set.count;
  }
  if (!spansTooMuch(c, n)) {
    if (n == 3) solveCubicBalanced(c, set);
    else solveQuarticBalanced(c, set);
  } else {
    set.trustworthy = false;
  }
  if (!set.trustworthy) {
    if (countFallback) fallbackCounter.add();
    return isolateRoots(c, n, roots);
  }
  sortSmall(set.x.data(), set.count);
  int count = 0;
  for (int i = 0; i < set.count; ++i) {
    if (count == 0 || set.x[i] != roots[count - 1]) roots[count++] = set.x[i];
  }
  return count;
}

// Any polynomial of degree <= 4 given as `size` coefficients: the whole
// pipeline of the file comment. `countFallback` is false for the quartic's
// resolvent cubic so the diagnostic counts the caller's solves only.
template <typename T>
int solveAny(const T* coeffs, int size, T* roots, bool countFallback) {
  Balanced<T> b;
  if (!balance(coeffs, size, b)) return 0;
  std::array<T, 4> scaled{};
  const int found = b.degree > 0 ? solveBalanced(b.c.data(), b.degree, scaled.data(), countFallback) : 0;
  int count = 0;
  bool zeroPlaced = !b.zeroRoot;
  for (int i = 0; i < found; ++i) {
    const T x = timesPowerOfTwo(scaled[i], b.shift);
    if (!std::isfinite(x)) continue;  // beyond the range of T: cannot be returned
    if (!zeroPlaced && x >= 0) {
      roots[count++] = 0;
      zeroPlaced = true;
    }
    // Roots that only differ below the range of T after unscaling are one.
    if (count == 0 || x != roots[count - 1]) roots[count++] = x;
  }
  if (!zeroPlaced) roots[count++] = 0;
  return count;
}

template <typename T>
int solveCubicInternal(const T* c, T* roots) {
  return solveAny(c, 4, roots, false);
}

}  // namespace

namespace roots_detail {
std::uint64_t fallbackCount() noexcept { return fallbackCounter.value(); }
}  // namespace roots_detail

template <typename T>
int solvePolynomial(std::span<const T> coeffs, T roots[4]) {
  // Zero coefficients above x^4 only lower the degree; a real degree above 4
  // is a caller bug (quartics are the highest degree the renderer makes).
  while (coeffs.size() > 5 && coeffs.back() == 0) coeffs = coeffs.first(coeffs.size() - 1);
  if (coeffs.size() > 5) {
    throw Error(ErrorKind::Internal,
                fmt::format("solvePolynomial: degree {} is above 4; only quadratics to quartics are supported",
                            coeffs.size() - 1));
  }
  if (coeffs.size() < 2) return 0;  // nothing, or a constant: no roots
  if constexpr (std::is_floating_point_v<T>)
    return solveAny(coeffs.data(), static_cast<int>(coeffs.size()), roots, true);
  else  // fixed point: its own method (render/solve/roots_fixed.cpp)
    return fixed_roots::solve(coeffs.data(), static_cast<int>(coeffs.size()), roots);
}

template <typename T>
int solveQuadratic(const T c[3], T roots[2]) {
  T all[4];
  const int n = solvePolynomial(std::span<const T>(c, 3), all);
  std::copy(all, all + n, roots);
  return n;
}

template <typename T>
int solveCubic(const T c[4], T roots[3]) {
  T all[4];
  const int n = solvePolynomial(std::span<const T>(c, 4), all);
  std::copy(all, all + n, roots);
  return n;
}

template <typename T>
int solveQuartic(const T c[5], T roots[4]) {
  return solvePolynomial(std::span<const T>(c, 5), roots);
}

template <typename T>
T evaluatePolynomial(std::span<const T> coeffs, T x) {
  if constexpr (!std::is_floating_point_v<T>) {
    return fixed_roots::evaluate(coeffs, x);
  } else {
    T s = 0;
    for (auto it = coeffs.rbegin(); it != coeffs.rend(); ++it) s = s * x + *it;
    return s;
  }
}

#define LATTICE_INSTANTIATE(T) \
  template int solveQuadratic<T>(const T[3], T[2]); \
  template int solveCubic<T>(const T[4], T[3]); \
  template int solveQuartic<T>(const T[5], T[4]); \
  template int solvePolynomial<T>(std::span<const T>, T[4]); \
  template T evaluatePolynomial<T>(std::span<const T>, T);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
