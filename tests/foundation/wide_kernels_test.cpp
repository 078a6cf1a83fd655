// The 32-bit-step kernels of foundation/wide_kernels.hpp, which Fixed32's *
// and / and the portable Int128's division run on the firmware, against the
// __int128 definitions foundation/fixed.hpp uses on the host: every result
// must be the same bits, on edge values and random operands of every length.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "foundation/fixed.hpp"
#include "foundation/wide_kernels.hpp"

namespace {

__extension__ typedef __int128 S;
__extension__ typedef unsigned __int128 U;
constexpr std::int64_t kMax = INT64_MAX;

std::int64_t saturate(S v) { return v > kMax ? kMax : v < -kMax ? -kMax : static_cast<std::int64_t>(v); }

// Fixed<F>::operator* and operator/ on __int128 (foundation/fixed.hpp).
template <int F>
std::int64_t referenceProduct(std::int64_t a, std::int64_t b) {
  S p = static_cast<S>(a) * b;
  const S half = static_cast<S>(1) << (F - 1);
  p = p >= 0 ? (p + half) >> F : -((-p + half) >> F);
  return saturate(p);
}
template <int F>
std::int64_t referenceQuotient(std::int64_t a, std::int64_t b) {
  if (b == 0) return a > 0 ? kMax : (a < 0 ? -kMax : 0);
  const S n = static_cast<S>(a) << F, d = b;
  const bool negative = (n < 0) != (d < 0);
  const S un = n < 0 ? -n : n, ud = d < 0 ? -d : d;
  const S q = (un + ud / 2) / ud;
  return saturate(negative ? -q : q);
}

// Raw values of every bit length, both signs, the edges and small ones.
std::vector<std::int64_t> raws() {
  std::mt19937_64 rng(24);
  std::vector<std::int64_t> v{0, 1, -1, 2, -2, 3, kMax, -kMax, INT64_MIN, std::int64_t(1) << 31, std::int64_t(1) << 32,
                              -(std::int64_t(1) << 32), (std::int64_t(1) << 32) - 1, std::int64_t(1) << 62,
                              (std::int64_t(1) << 62) - 1, std::int64_t(0xffffffff80000000ull >> 1)};
  for (int i = 0; i < 1500; ++i) {
    const int length = static_cast<int>(rng() % 63) + 1;
    const auto m = static_cast<std::int64_t>(rng() >> (64 - length));
    v.push_back((rng() & 1) ? -m : m);
  }
  return v;
}

}  // namespace

TEST_CASE("wide kernels: Fixed32's rounded, saturated product and quotient equal the __int128 definitions") {
  const auto v = raws();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = 0; j < v.size(); j += 3) {
      const std::int64_t a = v[i], b = v[j];
      INFO("a=" << a << " b=" << b);
      REQUIRE(lattice::wide::multiplyRaw<32>(a, b) == referenceProduct<32>(a, b));
      REQUIRE(lattice::wide::divideRaw<32>(a, b) == referenceQuotient<32>(a, b));
    }
}

TEST_CASE("wide kernels: quotients either side of one digit and products of one operand below 1.0") {
  // A quotient below 2^32 (|a| below |b|) takes one digit of the long
  // division, from 2^32 on two: dividends next to the divisor put the
  // quotient on both sides of that edge, for divisors of every length.
  std::mt19937_64 rng(32);
  for (int i = 0; i < 200000; ++i) {
    const int length = i % 63 + 1;
    const auto b = static_cast<std::int64_t>((rng() >> (64 - length)) | (std::uint64_t(1) << (length - 1)));
    const std::int64_t delta = static_cast<std::int64_t>(rng() % 7) - 3;
    const std::int64_t a = (rng() & 1) ? b + delta : -(b + delta), signedB = (rng() & 1) ? b : -b;
    INFO("a=" << a << " b=" << signedB);
    REQUIRE(lattice::wide::divideRaw<32>(a, signedB) == referenceQuotient<32>(a, signedB));
    // One operand below 2^32, the other of any length (a shift of 1..63: 64
    // would be undefined).
    const auto small = static_cast<std::int64_t>(rng() >> 32), large = static_cast<std::int64_t>(rng() >> (i % 63 + 1));
    REQUIRE(lattice::wide::multiplyRaw<32>(small, large) == referenceProduct<32>(small, large));
    REQUIRE(lattice::wide::multiplyRaw<32>(-large, small) == referenceProduct<32>(-large, small));
    const auto p = lattice::wide::multiply64By32(static_cast<std::uint64_t>(large), static_cast<std::uint32_t>(small));
    const U expected = static_cast<U>(static_cast<std::uint64_t>(large)) * static_cast<std::uint32_t>(small);
    REQUIRE(p.high == static_cast<std::uint64_t>(expected >> 64));
    REQUIRE(p.low == static_cast<std::uint64_t>(expected));
  }
}

TEST_CASE("wide kernels: other fraction bit counts agree too") {
  const auto v = raws();
  for (std::size_t i = 0; i < v.size(); i += 5)
    for (std::size_t j = 0; j < v.size(); j += 7) {
      const std::int64_t a = v[i], b = v[j];
      REQUIRE(lattice::wide::multiplyRaw<16>(a, b) == referenceProduct<16>(a, b));
      REQUIRE(lattice::wide::divideRaw<16>(a, b) == referenceQuotient<16>(a, b));
      REQUIRE(lattice::wide::multiplyRaw<48>(a, b) == referenceProduct<48>(a, b));
      REQUIRE(lattice::wide::divideRaw<48>(a, b) == referenceQuotient<48>(a, b));
    }
}

TEST_CASE("wide kernels: the long divisions equal __int128's quotient and remainder") {
  std::mt19937_64 rng(4125);
  for (int i = 0; i < 300000; ++i) {
    // 128 / 64 with a normalised divisor and high < d; the corners where a
    // digit's estimate is at its largest (high = d - 1, all-ones lows).
    const std::uint64_t d = rng() | (std::uint64_t(1) << 63);
    const std::uint64_t high = i % 5 == 0 ? d - 1 : rng() % d, low = i % 3 == 0 ? ~std::uint64_t(0) : rng();
    std::uint64_t r = 0;
    const std::uint64_t q = lattice::wide::divide128By64(high, low, d, r);
    const U n = static_cast<U>(high) << 64 | low;
    REQUIRE(q == static_cast<std::uint64_t>(n / d));
    REQUIRE(r == static_cast<std::uint64_t>(n % d));
    // 64 / 32 likewise.
    const std::uint32_t d32 = static_cast<std::uint32_t>(rng()) | 0x80000000u;
    const std::uint32_t high32 = i % 5 == 0 ? d32 - 1 : static_cast<std::uint32_t>(rng()) % d32;
    const std::uint32_t low32 = i % 3 == 0 ? 0xffffffffu : static_cast<std::uint32_t>(rng());
    std::uint32_t r32 = 0;
    const std::uint32_t q32 = lattice::wide::divide64By32(high32, low32, d32, r32);
    const std::uint64_t n64 = std::uint64_t(high32) << 32 | low32;
    REQUIRE(q32 == n64 / d32);
    REQUIRE(r32 == n64 % d32);
  }
}

TEST_CASE("wide kernels: the 128-bit product of 64-bit values") {
  std::mt19937_64 rng(1988);
  for (int i = 0; i < 300000; ++i) {
    const std::uint64_t a = i == 0 ? ~std::uint64_t(0) : rng() >> (rng() % 64), b = i == 0 ? a : rng() >> (rng() % 64);
    const auto p = lattice::wide::multiply64(a, b);
    const U expected = static_cast<U>(a) * b;
    REQUIRE(p.high == static_cast<std::uint64_t>(expected >> 64));
    REQUIRE(p.low == static_cast<std::uint64_t>(expected));
  }
}

TEST_CASE("wide kernels: the saturated sum and difference equal the __int128 definitions") {
  const auto v = raws();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = 0; j < v.size(); j += 2) {
      const std::int64_t a = v[i], b = v[j];
      REQUIRE(lattice::wide::addRaw(a, b) == saturate(static_cast<S>(a) + b));
      REQUIRE(lattice::wide::subtractRaw(a, b) == saturate(static_cast<S>(a) - b));
    }
}

TEST_CASE("isqrt: the CLZ-seeded Newton iteration gives floor(sqrt(n)) of every magnitude") {
  std::mt19937_64 rng(1988);
  const auto check = [](U n) {
    const U r = lattice::isqrt(n);
    INFO("n = " << static_cast<double>(n));
    REQUIRE(r * r <= n);
    if (r < (static_cast<U>(1) << 64) - 1) REQUIRE((r + 1) * (r + 1) > n);
  };
  for (U n : {U(0), U(1), U(2), U(3), U(4), U(0xffffffffu), U(1) << 32, (U(1) << 64) - 1, U(1) << 95, ~U(0) >> 1, ~U(0)})
    check(n);
  for (int i = 0; i < 200000; ++i) {
    const int length = static_cast<int>(rng() % 128) + 1;
    U n = static_cast<U>(rng()) << 64 | rng();
    n >>= 128 - length;
    check(n);
    const U r = lattice::isqrt(n);  // around the perfect squares
    check(r * r);
    if (r > 0) check(r * r - 1);
  }
}
