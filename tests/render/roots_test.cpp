// Polynomial root solvers (render/solve/roots.hpp) on the published hard cases.
//
// Every bound below comes from one formula, so it is stated once here. For a
// root r of multiplicity m of p(x) = sum c_k x^k, write S(r) = sum |c_k||r|^k
// and a_m = p^(m)(r) / m! (for m = 1, a_1 = p'(r)). A solver whose answer x
// satisfies |p(x)| <= K eps S(x) (backward error of K ulps) is off by at most
//     |x - r| <~ (K eps S(r) / |a_m|)^(1/m),
// i.e. eps times the root's condition number for simple roots and eps^(1/m)
// for multiple ones. No method can beat this order: rounding the coefficients
// to T already moves the roots that far. The solver accepts K = 64 before it
// falls back, the tests allow K = 128 (the coefficients themselves were
// rounded from the exact ones: one more ulp), a factor 2 for multiple roots
// (higher-order terms), plus 2 ulps of r.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "render/solve/roots.hpp"
#include "foundation/error.hpp"

namespace lattice::roots_detail {
std::uint64_t fallbackCount() noexcept;  // defined in render/solve/roots.cpp (diagnostic)
}

namespace {

using lattice::solvePolynomial;
using Real = long double;  // reference arithmetic, 64-bit mantissa on x86

struct ExpectedRoot {
  Real value;
  int multiplicity = 1;
};

// Coefficients (lowest power first) of scale * prod (x - r_i) * quadratic
// factors (x^2 + p x + q) for complex pairs, formed in long double.
std::vector<Real> expand(const std::vector<ExpectedRoot>& roots,
                         const std::vector<std::pair<Real, Real>>& complexFactors = {}, Real scale = 1) {
  std::vector<Real> c{scale};
  auto multiply = [&c](const std::vector<Real>& factor) {
    std::vector<Real> out(c.size() + factor.size() - 1, 0);
    for (size_t i = 0; i < c.size(); ++i)
      for (size_t j = 0; j < factor.size(); ++j) out[i + j] += c[i] * factor[j];
    c = out;
  };
  for (const auto& r : roots)
    for (int m = 0; m < r.multiplicity; ++m) multiply({-r.value, 1});
  for (const auto& [p, q] : complexFactors) multiply({q, p, 1});
  return c;
}

template <typename T>
std::vector<T> toT(const std::vector<Real>& c) {
  std::vector<T> out;
  for (Real v : c) out.push_back(static_cast<T>(v));
  return out;
}

// The allowed error for root r of the polynomial with coefficients c (as the
// solver saw them), following the formula in the file comment.
template <typename T>
Real allowedError(const std::vector<T>& c, const std::vector<ExpectedRoot>& all, const ExpectedRoot& r,
                  Real leading) {
  const Real eps = std::numeric_limits<T>::epsilon();
  Real s = 0;
  Real power = 1;
  for (T ck : c) {
    s += std::fabs(static_cast<Real>(ck)) * power;
    power *= std::fabs(r.value);
  }
  Real am = std::fabs(leading);
  for (const auto& other : all) {
    if (&other == &r) continue;
    am *= std::pow(std::fabs(r.value - other.value), static_cast<Real>(other.multiplicity));
  }
  // Complex factors are folded into `leading` by the callers that have them.
  const Real k = 128;
  Real bound = (k * eps * s) / am;
  if (r.multiplicity > 1) bound = 2 * std::pow(bound, 1 / static_cast<Real>(r.multiplicity));
  return bound + 2 * eps * std::fabs(r.value);
}

struct CheckResult {
  Real maxRelativeError = 0;  // over expected roots, |x - r| / |r|
  Real maxBoundRatio = 0;     // |x - r| / allowed
  int count = 0;              // roots returned
};

// Every expected root has a returned root within its bound, every returned
// root is within the bound of some expected root (no spurious roots), the
// roots are ascending, and the count is between the number of distinct roots
// and the number counted with multiplicity.
template <typename T>
CheckResult checkRoots(const std::vector<T>& c, const std::vector<ExpectedRoot>& expected, Real leading = 1,
                       std::vector<Real> allowedOverride = {}) {
  T roots[4] = {};
  const int n = solvePolynomial<T>(std::span<const T>(c), roots);
  INFO("coefficients: " << [&] {
    std::string s;
    for (T v : c) s += std::to_string(static_cast<double>(v)) + " ";
    return s;
  }());
  int withMultiplicity = 0;
  for (const auto& r : expected) withMultiplicity += r.multiplicity;
  REQUIRE(n >= static_cast<int>(expected.size()));
  REQUIRE(n <= withMultiplicity);
  for (int i = 1; i < n; ++i) REQUIRE(roots[i - 1] <= roots[i]);

  std::vector<Real> allowed;
  for (size_t i = 0; i < expected.size(); ++i) {
    allowed.push_back(allowedOverride.empty() ? allowedError(c, expected, expected[i], leading)
                                              : allowedOverride[i]);
  }
  CheckResult result;
  result.count = n;
  for (size_t i = 0; i < expected.size(); ++i) {
    Real best = std::numeric_limits<Real>::infinity();
    for (int j = 0; j < n; ++j) best = std::min(best, std::fabs(static_cast<Real>(roots[j]) - expected[i].value));
    INFO("expected root " << static_cast<double>(expected[i].value) << " closest error "
                          << static_cast<double>(best) << " allowed " << static_cast<double>(allowed[i]));
    CHECK(best <= allowed[i]);
    if (expected[i].value != 0)
      result.maxRelativeError = std::max(result.maxRelativeError, best / std::fabs(expected[i].value));
    result.maxBoundRatio = std::max(result.maxBoundRatio, best / allowed[i]);
  }
  for (int j = 0; j < n; ++j) {
    bool near = false;
    for (size_t i = 0; i < expected.size(); ++i)
      near = near || std::fabs(static_cast<Real>(roots[j]) - expected[i].value) <= allowed[i];
    INFO("returned root " << static_cast<double>(roots[j]));
    CHECK(near);
  }
  return result;
}

template <typename T>
CheckResult checkExpanded(const std::vector<ExpectedRoot>& expected, Real scale = 1) {
  return checkRoots<T>(toT<T>(expand(expected, {}, scale)), expected, scale);
}

// Relative error bound for a simple, well-conditioned root, for the cases
// where the test states a fixed number of ulps rather than the formula.
template <typename T>
Real ulps(Real r, Real count) {
  return count * std::numeric_limits<T>::epsilon() * std::fabs(r);
}

}  // namespace

TEST_CASE("roots: spread over nine orders of magnitude keep full relative accuracy", "[roots]") {
  // Roots 1e9, 1e6, 1e3, 1: each root's condition number is below 3 (the
  // coefficients are dominated by the products that contain the root), so
  // each comes back within a few ulps relative, not just absolutely.
  const std::vector<ExpectedRoot> roots{{1e9L}, {1e6L}, {1e3L}, {1}};
  const auto c = toT<double>(expand(roots));
  std::vector<Real> allowed;
  for (const auto& r : roots) allowed.push_back(ulps<double>(r.value, 8));
  const CheckResult result = checkRoots(c, roots, 1, allowed);
  CHECK(result.maxRelativeError <= 8 * std::numeric_limits<double>::epsilon());
  // Negative and mixed signs too.
  const std::vector<ExpectedRoot> mixed{{-1e9L}, {1e6L}, {-1e3L}, {1}};
  std::vector<Real> allowedMixed;
  for (const auto& r : mixed) allowedMixed.push_back(ulps<double>(r.value, 8));
  checkRoots(toT<double>(expand(mixed)), mixed, 1, allowedMixed);
}

TEST_CASE("roots: a cluster 2, 2.001, 2.002, 2.003 is resolved to its condition number", "[roots]") {
  // The cluster's condition number is about 6e10: rounding the coefficients
  // to double alone moves the roots by ~1e-5 relative; every root must be
  // found, as four distinct roots, within the formula's bound.
  const std::vector<ExpectedRoot> roots{{2}, {2.001L}, {2.002L}, {2.003L}};
  const auto c = toT<double>(expand(roots));
  double out[4];
  REQUIRE(solvePolynomial<double>(c, out) == 4);
  checkExpanded<double>(roots);
}

TEST_CASE("roots: multiple roots are found to eps^(1/m)", "[roots]") {
  SECTION("quadruple root") { checkExpanded<double>({{1.5L, 4}}); }
  SECTION("quadruple root at a non-representable value") { checkExpanded<double>({{0.1L, 4}}); }
  SECTION("two double roots") { checkExpanded<double>({{1, 2}, {3, 2}}); }
  SECTION("two close double roots of opposite sign") { checkExpanded<double>({{-0.7L, 2}, {0.9L, 2}}); }
  SECTION("a double root and two simple roots") { checkExpanded<double>({{2, 2}, {-1}, {5}}); }
  SECTION("triple root and a simple root") { checkExpanded<double>({{-3, 3}, {0.25L}}); }
  SECTION("cubic triple root") { checkExpanded<double>({{2, 3}}); }
  SECTION("quadratic double root") { checkExpanded<double>({{-1.0L / 3, 2}}); }
}

TEST_CASE("roots: huge and tiny coefficient scales do not change the roots", "[roots]") {
  const std::vector<ExpectedRoot> roots{{-3}, {-1}, {2}, {7}};
  for (Real scale : {1e30L, 1e-30L, 1e300L, 1e-300L}) {
    INFO("scale " << static_cast<double>(scale));
    checkExpanded<double>(roots, scale);
  }
  // Scaled roots (x -> 1e20 x and 1e-20 x): the solver balances x too.
  for (Real s : {1e20L, 1e-20L}) {
    const std::vector<ExpectedRoot> scaled{{-3 * s}, {-1 * s}, {2 * s}, {7 * s}};
    checkExpanded<double>(scaled);
  }
  // Float: 1e30 coefficients overflow if squared; the scaling keeps it exact.
  for (Real scale : {1e30L, 1e-30L}) checkExpanded<float>(roots, scale);
}

TEST_CASE("roots: only the real roots of complex-pair cases are returned", "[roots]") {
  // (x^2 + 1)(x - 1)(x - 2): the pair's |p| is far from zero on the real line.
  {
    const std::vector<ExpectedRoot> roots{{1}, {2}};
    const auto c = toT<double>(expand(roots, {{0, 1}}));
    // p = (x^2+1) * (x-1)(x-2): a_1 gains the factor |r^2 + 1|.
    std::vector<Real> allowed{ulps<double>(1, 16), ulps<double>(2, 16)};
    checkRoots(c, roots, 1, allowed);
  }
  {  // (x^2 + 2x + 5)(x^2 + 1): no real roots at all.
    const auto c = toT<double>(expand({}, {{2, 5}, {0, 1}}));
    double out[4];
    CHECK(solvePolynomial<double>(c, out) == 0);
  }
  {  // A narrow pair 1 +- 0.1i next to real roots -4 and 3.
    const auto c = toT<double>(expand({{-4}, {3}}, {{-2, 1.01L}}));
    double out[4];
    REQUIRE(solvePolynomial<double>(c, out) == 2);
    CHECK(std::fabs(out[0] + 4) <= ulps<double>(4, 16));
    CHECK(std::fabs(out[1] - 3) <= ulps<double>(3, 16));
  }
  {  // Cubic with one real root and a pair: (x - 0.5)(x^2 + x + 1).
    const auto c = toT<double>(expand({{0.5L}}, {{1, 1}}));
    double out[4];
    REQUIRE(solvePolynomial<double>(c, out) == 1);
    CHECK(std::fabs(out[0] - 0.5) <= ulps<double>(0.5, 4));
  }
  {  // Quadratic with a pair.
    const double c[3] = {1, 1, 1};
    double out[2];
    CHECK(lattice::solveQuadratic(c, out) == 0);
  }
}

TEST_CASE("roots: degenerate inputs: leading zeros, zero roots, constants, NaN and inf", "[roots]") {
  double out[4];
  SECTION("leading zeros lower the degree") {
    const double quadraticAsQuartic[5] = {6, -5, 1, 0, 0};  // (x-2)(x-3)
    REQUIRE(lattice::solveQuartic(quadraticAsQuartic, out) == 2);
    CHECK(out[0] == 2.0);
    CHECK(out[1] == 3.0);
    const double linearAsCubic[4] = {-3, 2, 0, 0};
    REQUIRE(lattice::solveCubic(linearAsCubic, out) == 1);
    CHECK(out[0] == 1.5);
    const double linear[3] = {1, 3, 0};
    REQUIRE(lattice::solveQuadratic(linear, out) == 1);
    CHECK(out[0] == -1.0 / 3.0);
  }
  SECTION("constants and the zero polynomial have no roots") {
    const double zero[5] = {0, 0, 0, 0, 0};
    CHECK(lattice::solveQuartic(zero, out) == 0);
    const double constant[5] = {4, 0, 0, 0, 0};
    CHECK(lattice::solveQuartic(constant, out) == 0);
    CHECK(solvePolynomial<double>(std::span<const double>(), out) == 0);
  }
  SECTION("NaN and infinite coefficients give no roots") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const double withNan[5] = {1, 2, nan, 0, 1};
    CHECK(lattice::solveQuartic(withNan, out) == 0);
    const double withInf[4] = {1, -inf, 0, 1};
    CHECK(lattice::solveCubic(withInf, out) == 0);
    const float withInfF[3] = {1, 0, std::numeric_limits<float>::infinity()};
    float outF[2];
    CHECK(lattice::solveQuadratic(withInfF, outF) == 0);
  }
  SECTION("zero roots are exact and reported once") {
    const double xSquaredTimes[5] = {0, 0, 2, -3, 1};  // x^2 (x-1)(x-2)
    REQUIRE(lattice::solveQuartic(xSquaredTimes, out) == 3);
    CHECK(out[0] == 0.0);
    CHECK(std::fabs(out[1] - 1) <= ulps<double>(1, 2));
    CHECK(std::fabs(out[2] - 2) <= ulps<double>(2, 2));
    const double negativeAndZero[4] = {0, 2, 3, 1};  // x (x+1)(x+2)
    REQUIRE(lattice::solveCubic(negativeAndZero, out) == 3);
    CHECK(std::fabs(out[0] + 2) <= ulps<double>(2, 2));
    CHECK(std::fabs(out[1] + 1) <= ulps<double>(1, 2));
    CHECK(out[2] == 0.0);
    const double xFourth[5] = {0, 0, 0, 0, 3};
    REQUIRE(lattice::solveQuartic(xFourth, out) == 1);
    CHECK(out[0] == 0.0);
  }
  SECTION("zero coefficients above x^4 are ignored, a real degree 5 is refused") {
    const double padded[6] = {6, -5, 1, 0, 0, 0};
    REQUIRE(solvePolynomial<double>(padded, out) == 2);
    const double quintic[6] = {1, 0, 0, 0, 0, 1};
    CHECK_THROWS_AS(solvePolynomial<double>(quintic, out), lattice::Error);
  }
}

TEST_CASE("roots: the quadratic has no cancellation", "[roots]") {
  // x^2 - (1e8 + 1e-8) x + 1: the textbook formula loses the small root.
  const std::vector<ExpectedRoot> roots{{1e-8L}, {1e8L}};
  const auto c = toT<double>(expand(roots));
  checkRoots(c, roots, 1, {ulps<double>(1e-8L, 2), ulps<double>(1e8L, 2)});
  // Nearly double roots 1 and 1 + 2^-26: b^2 - 4ac cancels to ~2^-52 of b^2;
  // Kahan's fma discriminant keeps them distinct and accurate.
  const Real delta = std::ldexp(1.0L, -26);
  const std::vector<ExpectedRoot> close{{1}, {1 + delta}};
  double out[4];
  REQUIRE(solvePolynomial<double>(toT<double>(expand(close)), out) == 2);
  checkExpanded<double>(close);
}

TEST_CASE("roots: cubics: spread, clustered, mixed-sign", "[roots]") {
  checkExpanded<double>({{1e6L}, {1}, {1e-6L}});
  checkExpanded<double>({{-1e6L}, {1}, {-1e-6L}});
  checkExpanded<double>({{1}, {1.001L}, {1.002L}});
  checkExpanded<double>({{-5}, {0.5L}, {100}}, 1e-20L);
}

namespace {

// log-uniform magnitude in [10^lo, 10^hi] with a random sign
Real randomRoot(std::mt19937_64& rng, Real lo, Real hi) {
  std::uniform_real_distribution<double> exponent(static_cast<double>(lo), static_cast<double>(hi));
  std::bernoulli_distribution negative(0.5);
  const Real v = std::pow(10.0L, static_cast<Real>(exponent(rng)));
  return negative(rng) ? -v : v;
}

template <typename T>
void randomSuite(const char* label, int degree, int cases, Real lo, Real hi, bool withPair, Real distinctSeparation) {
  std::mt19937_64 rng(20260122);
  CheckResult worst;
  const std::uint64_t fallbacksBefore = lattice::roots_detail::fallbackCount();
  int countMismatches = 0;
  for (int i = 0; i < cases; ++i) {
    // Roots closer than distinctSeparation (relative) are redrawn: closer ones
    // are a cluster, covered by the hard cases, and the first-order bound
    // below does not apply to them.
    std::vector<ExpectedRoot> roots;
    const int realCount = withPair ? degree - 2 : degree;
    while (static_cast<int>(roots.size()) < realCount) {
      const Real candidate = randomRoot(rng, lo, hi);
      bool separated = true;
      for (const auto& r : roots)
        separated = separated && std::fabs(candidate - r.value) >
                                     distinctSeparation * std::max(std::fabs(candidate), std::fabs(r.value));
      if (separated) roots.push_back({candidate});
    }
    std::vector<std::pair<Real, Real>> pairs;
    Real leading = 1;
    if (withPair) {
      // A pair re +- i im with im at least 10% of |re|, so it is clearly complex.
      const Real re = randomRoot(rng, lo, hi);
      std::uniform_real_distribution<double> ratio(0.1, 10.0);
      const Real im = std::fabs(re) * static_cast<Real>(ratio(rng));
      pairs.push_back({-2 * re, re * re + im * im});
      leading = 1;  // folded into the override below
    }
    const auto c = toT<T>(expand(roots, pairs));
    std::vector<Real> allowed;
    for (const auto& r : roots) {
      Real bound = allowedError(c, roots, r, leading);
      for (const auto& [p, q] : pairs) bound /= std::fabs(r.value * r.value + p * r.value + q);
      allowed.push_back(bound);
    }
    const CheckResult one = checkRoots(c, roots, leading, allowed);
    worst.maxRelativeError = std::max(worst.maxRelativeError, one.maxRelativeError);
    worst.maxBoundRatio = std::max(worst.maxBoundRatio, one.maxBoundRatio);
    // Separated roots must all be reported individually.
    if (one.count != realCount) ++countMismatches;
  }
  CHECK(countMismatches == 0);
  std::printf("roots %s: %d cases, max relative error %.3g, max error / bound %.3g, fallbacks %llu\n", label,
              cases, static_cast<double>(worst.maxRelativeError), static_cast<double>(worst.maxBoundRatio),
              static_cast<unsigned long long>(lattice::roots_detail::fallbackCount() - fallbacksBefore));
}

}  // namespace

TEST_CASE("roots: random polynomials from known roots, double", "[roots]") {
  randomSuite<double>("double quartic 4 real", 4, 4000, -3, 3, false, 1e-6L);
  randomSuite<double>("double quartic 2 real + pair", 4, 2000, -3, 3, true, 1e-6L);
  randomSuite<double>("double cubic 3 real", 3, 2000, -3, 3, false, 1e-6L);
  randomSuite<double>("double quadratic", 2, 2000, -4, 4, false, 1e-6L);
}

TEST_CASE("roots: random polynomials from known roots, float", "[roots]") {
  randomSuite<float>("float quartic 4 real", 4, 3000, -2, 2, false, 1e-2L);
  randomSuite<float>("float quartic 2 real + pair", 4, 1000, -2, 2, true, 1e-2L);
  randomSuite<float>("float cubic 3 real", 3, 1000, -2, 2, false, 1e-2L);
}

TEST_CASE("roots: float instantiation on the hard cases", "[roots]") {
  // Same formula with float's eps: the spread case keeps a few float ulps, the
  // multiple roots eps_f^(1/m) (about 1.8e-2 relative for a quadruple root).
  checkExpanded<float>({{1e4L}, {1e2L}, {1}, {1e-2L}});
  checkExpanded<float>({{1.5L, 4}});
  checkExpanded<float>({{1, 2}, {3, 2}});
  checkExpanded<float>({{2, 2}, {-1}, {5}});
  checkExpanded<float>({{-3}, {-1}, {2}, {7}});
  checkExpanded<float>({{1e3L}, {1}, {1e-3L}});
  const float q[3] = {1.0f, -1e4f, 1.0f};  // no cancellation in float either
  float out[2];
  REQUIRE(lattice::solveQuadratic(q, out) == 2);
  CHECK(std::fabs(out[0] - 1e-4f) <= 2 * std::numeric_limits<float>::epsilon() * 1e-4f);
  CHECK(std::fabs(out[1] - 1e4f) <= 2 * std::numeric_limits<float>::epsilon() * 1e4f);
}

namespace {

// Ray o + t d against the torus (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p_x^2 + p_y^2),
// expanded in t (lowest power first), in long double.
std::vector<Real> torusQuartic(const Real o[3], const Real d[3], Real major, Real minor) {
  const Real dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const Real od = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const Real oo = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
  const Real k = oo + major * major - minor * minor;
  // (dd t^2 + 2 od t + k)^2 - 4 R^2 ((dx t + ox)^2 + (dy t + oy)^2)
  const Real dxy = d[0] * d[0] + d[1] * d[1];
  const Real oxy = o[0] * d[0] + o[1] * d[1];
  const Real ooxy = o[0] * o[0] + o[1] * o[1];
  const Real r4 = 4 * major * major;
  return {k * k - r4 * ooxy, 4 * od * k - r4 * 2 * oxy, 4 * od * od + 2 * dd * k - r4 * dxy, 4 * dd * od, dd * dd};
}

}  // namespace

TEST_CASE("roots: torus ray polynomials", "[roots]") {
  const Real major = 1.0L;
  const Real minor = 0.25L;
  SECTION("rays in the torus plane hit where the geometry says") {
    // A ray along x at height y = h, from x = -L: hits at x = +-sqrt((R +- r)^2 - h^2).
    // Farther origins pack the four roots into a relative cluster whose
    // condition number grows like distance^3: at 1e4 rounding the
    // coefficients to double already merges them (a renderer should start
    // the ray near the bounding box, which is what the quartic helper does).
    for (Real distance : {3.0L, 30.0L, 100.0L}) {
      for (Real h : {0.0L, 0.3L, 0.8L, 1.1L, 1.2499L}) {
        const Real o[3] = {-distance, h, 0};
        const Real d[3] = {1, 0, 0};
        std::vector<ExpectedRoot> expected;
        for (Real radius : {major - minor, major + minor}) {
          if (radius * radius <= h * h) continue;
          const Real x = std::sqrt(radius * radius - h * h);
          expected.push_back({distance - x});
          expected.push_back({distance + x});
        }
        std::sort(expected.begin(), expected.end(),
                  [](const ExpectedRoot& a, const ExpectedRoot& b) { return a.value < b.value; });
        const auto c = toT<double>(torusQuartic(o, d, major, minor));
        INFO("distance " << static_cast<double>(distance) << " height " << static_cast<double>(h));
        if (expected.empty()) {
          double out[4];
          CHECK(solvePolynomial<double>(c, out) == 0);
        } else {
          checkExpanded<double>(expected);  // the same roots from exact coefficients
          checkRoots(c, expected, c.back());
        }
      }
    }
  }
  SECTION("random rays: every root is a root, and no sign change is missed") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 300; ++i) {
      const Real o[3] = {4 * u(rng), 4 * u(rng), 2 + 2 * u(rng)};
      // Aim near the torus so most rays hit.
      const Real target[3] = {1.2L * u(rng), 1.2L * u(rng), 0.3L * u(rng)};
      Real d[3] = {target[0] - o[0], target[1] - o[1], target[2] - o[2]};
      const auto cl = torusQuartic(o, d, major, minor);
      const auto c = toT<double>(cl);
      double out[4];
      const int n = solvePolynomial<double>(c, out);
      // Independent count of sign changes of p(t) on a fine grid, in long
      // double, over the span where the ray can meet the torus.
      int signChanges = 0;
      Real previous = 0;
      const int samples = 20000;
      for (int s = 0; s <= samples; ++s) {
        const Real t = -1 + 4 * static_cast<Real>(s) / samples;
        Real v = 0;
        for (auto it = cl.rbegin(); it != cl.rend(); ++it) v = v * t + *it;
        if (s > 0 && ((v < 0) != (previous < 0))) ++signChanges;
        previous = v;
      }
      INFO("ray " << i);
      CHECK(n >= signChanges);
      for (int k = 0; k < n; ++k) {
        Real v = 0;
        Real scale = 0;
        for (auto it = c.rbegin(); it != c.rend(); ++it) {
          v = v * out[k] + *it;
          scale = scale * std::fabs(out[k]) + std::fabs(*it);
        }
        CHECK(std::fabs(v) <= 128 * std::numeric_limits<double>::epsilon() * scale);
      }
    }
  }
}

TEST_CASE("roots: the isolation fallback takes over where the closed form is not good enough", "[roots]") {
  // The torus ray from distance 100 at height 1.1: four roots within 1% of
  // each other, where the Ferrari factorisation cannot be refined to a few
  // ulps; isolation must still find both real roots.
  {
    const std::uint64_t before = lattice::roots_detail::fallbackCount();
    const Real o[3] = {-100, 1.1L, 0};
    const Real d[3] = {1, 0, 0};
    const auto c = toT<double>(torusQuartic(o, d, 1, 0.25L));
    const Real x = std::sqrt(1.25L * 1.25L - 1.1L * 1.1L);
    const std::vector<ExpectedRoot> roots{{100 - x}, {100 + x}};
    // The other two roots are the pair 100 +- i sqrt(1.1^2 - 0.75^2).
    const Real pairSquare = 1.1L * 1.1L - 0.75L * 0.75L;
    std::vector<Real> allowed;
    for (const auto& r : roots)
      allowed.push_back(allowedError(c, roots, r, 1) / ((r.value - 100) * (r.value - 100) + pairSquare));
    checkRoots(c, roots, 1, allowed);
    CHECK(lattice::roots_detail::fallbackCount() == before + 1);
  }
  // Float coefficients spanning more than 2^42 once balanced: the resolvent
  // would multiply three of them, so isolation is used from the start.
  {
    const std::uint64_t before = lattice::roots_detail::fallbackCount();
    const std::vector<ExpectedRoot> roots{{1e14L}, {1}, {1e-14L}};
    checkExpanded<float>(roots);
    CHECK(lattice::roots_detail::fallbackCount() == before + 1);
  }
}

namespace {

// Coefficients of random sign and magnitude 10^[-range, range], some zero:
// whatever comes out must be sorted, finite and at most the degree in
// number; with `strict`, each root must also be a root (backward error of a
// few ulps, evaluated in long double). The solver promises that when no
// coefficient is more than the exponent range of T below another after
// balancing, which |c_k| in 10^[-75, 75] (double) or 10^[-9, 9] (float)
// guarantees; beyond that, terms flush to zero (docs/roots.md, "Range") and
// only the "no crash, hang or garbage" part is checked.
template <typename T>
void arbitraryCoefficients(Real range, int cases, bool strict) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> exponent(-static_cast<double>(range), static_cast<double>(range));
  std::uniform_int_distribution<int> pick(0, 9);
  int worstUlps = 0;
  long rootCount = 0;
  long rootsWithinTolerance = 0;
  for (int i = 0; i < cases; ++i) {
    T c[5];
    for (T& v : c) {
      const int kind = pick(rng);
      v = kind == 0 ? T(0) : static_cast<T>((kind % 2 ? -1 : 1) * std::pow(10.0L, static_cast<Real>(exponent(rng))));
    }
    T out[4];
    const int n = lattice::solveQuartic(c, out);
    int degree = 4;
    while (degree > 0 && c[degree] == 0) --degree;
    INFO("case " << i << " coefficients " << static_cast<double>(c[0]) << " " << static_cast<double>(c[1]) << " "
                 << static_cast<double>(c[2]) << " " << static_cast<double>(c[3]) << " "
                 << static_cast<double>(c[4]));
    REQUIRE(n >= 0);
    REQUIRE(n <= degree);
    for (int k = 0; k < n; ++k) {
      REQUIRE(std::isfinite(out[k]));
      if (k > 0) REQUIRE(out[k - 1] < out[k]);
      Real v = 0;
      Real scale = 0;
      for (int j = 4; j >= 0; --j) {
        v = v * out[k] + c[j];
        scale = scale * std::fabs(static_cast<Real>(out[k])) + std::fabs(static_cast<Real>(c[j]));
      }
      // Relative to the size of the terms, and allowing for the root being
      // rounded to T (one ulp of x moves p by about |x p'(x)| eps).
      Real derivative = 0;
      for (int j = 4; j >= 1; --j) derivative = derivative * out[k] + j * static_cast<Real>(c[j]);
      const Real slack = std::fabs(static_cast<Real>(out[k]) * derivative);
      const Real ulpsOff = v == 0 ? 0 : std::fabs(v) / ((scale + slack) * std::numeric_limits<T>::epsilon());
      if (strict) CHECK(ulpsOff <= 64);
      ++rootCount;
      if (ulpsOff <= 64) ++rootsWithinTolerance;
      worstUlps = std::max(worstUlps, static_cast<int>(std::min<Real>(std::ceil(ulpsOff), 1e9L)));
    }
  }
  std::printf("roots arbitrary %s coefficients in 10^[-%g, %g]: %d cases, %ld of %ld roots within 64 ulps"
              " of backward error, worst %s%d ulps\n",
              sizeof(T) == 4 ? "float" : "double", static_cast<double>(range), static_cast<double>(range), cases,
              rootsWithinTolerance, rootCount, worstUlps >= 1000000000 ? ">= " : "", worstUlps);
}

}  // namespace

TEST_CASE("roots: arbitrary coefficients: sorted, finite, real roots, no hang", "[roots]") {
  arbitraryCoefficients<double>(75, 20000, true);
  arbitraryCoefficients<float>(9, 20000, true);
  arbitraryCoefficients<double>(300, 5000, false);
  arbitraryCoefficients<float>(37, 5000, false);
}

TEST_CASE("roots: evaluatePolynomial is Horner, lowest power first", "[roots]") {
  const double c[4] = {1, -2, 0, 3};  // 1 - 2x + 3x^3
  CHECK(lattice::evaluatePolynomial<double>(c, 2.0) == 1 - 4 + 24);
  const float cf[2] = {0.5f, 2.0f};
  CHECK(lattice::evaluatePolynomial<float>(cf, -1.0f) == -1.5f);
  CHECK(lattice::evaluatePolynomial<double>(std::span<const double>(), 3.0) == 0.0);
}
