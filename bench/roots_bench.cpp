// Median time per solve of the polynomial root solvers (render/solve/roots.hpp),
// float and double, on fixed random sets (seeded, so runs are comparable):
//   quadratic / cubic / quartic: roots log-uniform in +-10^[-2, 2], half of
//     the cubics and quartics with a complex pair instead of two real roots;
//   torus rays: quartics of random rays aimed at a torus (R = 1, r = 0.25),
//     the polynomials the quartic primitives actually produce.
// Each set is solved 31 times; the median over those passes of (pass time /
// set size) is printed, with how many solves of the set needed the isolation
// fallback. Time is the thread's CPU time, not wall time, so other processes
// sharing the cores do not inflate it (they still cost cache misses).
// Figures quoted in docs/roots.md come from this program.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include <time.h>

#include <fmt/format.h>

#include "render/solve/roots.hpp"

namespace lattice::roots_detail {
std::uint64_t fallbackCount() noexcept;  // defined in render/solve/roots.cpp (diagnostic)
}

namespace {

constexpr int kSetSize = 4096;
constexpr int kPasses = 31;

using Polynomial = std::array<double, 5>;

double threadCpuNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}  // lowest power first, unused tail zero

double randomRoot(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> exponent(-2, 2);
  std::bernoulli_distribution negative(0.5);
  const double v = std::pow(10.0, exponent(rng));
  return negative(rng) ? -v : v;
}

// Multiplies the polynomial `p` of degree `degree` by (x^2 + b x + c) or (x - r).
void multiply(Polynomial& p, int& degree, double b, double c, bool quadratic) {
  Polynomial out{};
  const std::array<double, 3> factor = quadratic ? std::array<double, 3>{c, b, 1} : std::array<double, 3>{-b, 1, 0};
  const int factorDegree = quadratic ? 2 : 1;
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; j <= factorDegree; ++j) out[i + j] += p[i] * factor[j];
  p = out;
  degree += factorDegree;
}

std::vector<Polynomial> fromRoots(int degree, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Polynomial> set;
  for (int i = 0; i < kSetSize; ++i) {
    Polynomial p{1, 0, 0, 0, 0};
    int d = 0;
    const bool withPair = degree >= 3 && i % 2 == 1;
    if (withPair) {
      const double re = randomRoot(rng);
      const double im = std::abs(re) * std::uniform_real_distribution<double>(0.1, 10)(rng);
      multiply(p, d, -2 * re, re * re + im * im, true);
    }
    while (d < degree) multiply(p, d, randomRoot(rng), 0, false);
    set.push_back(p);
  }
  return set;
}

std::vector<Polynomial> torusRays(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double major = 1;
  const double minor = 0.25;
  std::vector<Polynomial> set;
  for (int i = 0; i < kSetSize; ++i) {
    const double o[3] = {4 * u(rng), 4 * u(rng), 2 + 2 * u(rng)};
    const double target[3] = {1.2 * u(rng), 1.2 * u(rng), 0.3 * u(rng)};
    const double d[3] = {target[0] - o[0], target[1] - o[1], target[2] - o[2]};
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double od = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
    const double oo = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
    const double k = oo + major * major - minor * minor;
    const double dxy = d[0] * d[0] + d[1] * d[1];
    const double oxy = o[0] * d[0] + o[1] * d[1];
    const double ooxy = o[0] * o[0] + o[1] * o[1];
    const double r4 = 4 * major * major;
    set.push_back({k * k - r4 * ooxy, 4 * od * k - r4 * 2 * oxy, 4 * od * od + 2 * dd * k - r4 * dxy,
                   4 * dd * od, dd * dd});
  }
  return set;
}

template <typename T>
void run(const char* label, const std::vector<Polynomial>& set, int degree) {
  std::vector<std::array<T, 5>> coefficients;
  for (const auto& p : set) {
    std::array<T, 5> c{};
    for (int k = 0; k <= degree; ++k) c[k] = static_cast<T>(p[k]);
    coefficients.push_back(c);
  }
  const std::size_t size = static_cast<std::size_t>(degree) + 1;
  // One untimed pass: warms caches and counts the fallbacks of the set.
  const std::uint64_t before = lattice::roots_detail::fallbackCount();
  long totalRoots = 0;
  for (const auto& c : coefficients) {
    T roots[4];
    totalRoots += lattice::solvePolynomial<T>(std::span<const T>(c.data(), size), roots);
  }
  const std::uint64_t fallbacks = lattice::roots_detail::fallbackCount() - before;

  std::vector<double> nsPerSolve;
  volatile T sink = 0;  // keeps the solves from being optimised away
  for (int pass = 0; pass < kPasses; ++pass) {
    T accumulate = 0;
    const double start = threadCpuNanoseconds();
    for (const auto& c : coefficients) {
      T roots[4] = {};
      const int n = lattice::solvePolynomial<T>(std::span<const T>(c.data(), size), roots);
      accumulate += static_cast<T>(n) + roots[0];
    }
    const double stop = threadCpuNanoseconds();
    sink = sink + accumulate;
    nsPerSolve.push_back((stop - start) / kSetSize);
  }
  std::sort(nsPerSolve.begin(), nsPerSolve.end());
  fmt::print("{:<10} {:<7} {:>8.1f} ns/solve (min {:>7.1f})   {:>5.2f} real roots/solve   fallback {} of {}\n",
             label, sizeof(T) == 4 ? "float" : "double", nsPerSolve[kPasses / 2], nsPerSolve.front(),
             static_cast<double>(totalRoots) / kSetSize, fallbacks, kSetSize);
}

}  // namespace

int main() {
  fmt::print("roots_bench: {} polynomials per set, median of {} passes\n", kSetSize, kPasses);
  const auto quadratics = fromRoots(2, 1);
  const auto cubics = fromRoots(3, 2);
  const auto quartics = fromRoots(4, 3);
  const auto torus = torusRays(4);
  for (int typeIndex = 0; typeIndex < 2; ++typeIndex) {
    if (typeIndex == 0) {
      run<double>("quadratic", quadratics, 2);
      run<double>("cubic", cubics, 3);
      run<double>("quartic", quartics, 4);
      run<double>("torus ray", torus, 4);
    } else {
      run<float>("quadratic", quadratics, 2);
      run<float>("cubic", cubics, 3);
      run<float>("quartic", quartics, 4);
      run<float>("torus ray", torus, 4);
    }
  }
  return 0;
}
