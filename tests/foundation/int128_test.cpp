// The portable 128-bit integer (foundation/int128.hpp), used by Fixed32 on
// 32-bit targets such as the firmware, against GCC's __int128 on the host:
// every operator the fixed-point code uses, on edge values and random ones
// of every magnitude, must give the same bits.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "foundation/int128.hpp"

namespace {

__extension__ typedef __int128 S;
__extension__ typedef unsigned __int128 U;
using W = lattice::Wide128<true>;
using WU = lattice::Wide128<false>;

U bits(W w) { return static_cast<U>(w.high()) << 64 | w.low(); }
U bits(WU w) { return static_cast<U>(w.high()) << 64 | w.low(); }
W wide(S v) { return W::fromHalves(static_cast<std::uint64_t>(static_cast<U>(v) >> 64), static_cast<std::uint64_t>(v)); }
WU wideU(U v) { return WU::fromHalves(static_cast<std::uint64_t>(v >> 64), static_cast<std::uint64_t>(v)); }

// Values of every bit length, both signs, and the edges.
std::vector<S> samples() {
  std::mt19937_64 rng(17);
  std::vector<S> v{0, 1, -1, 2, -2, INT64_MAX, INT64_MIN, static_cast<S>(UINT64_MAX), static_cast<S>(1) << 64,
                   -(static_cast<S>(1) << 64), (static_cast<S>(1) << 100) - 1, static_cast<S>(1) << 126};
  for (int i = 0; i < 400; ++i) {
    const int length = static_cast<int>(rng() % 126) + 1;
    U u = static_cast<U>(rng()) << 64 | rng();
    u >>= 128 - length;
    v.push_back((rng() & 1) ? -static_cast<S>(u) : static_cast<S>(u));
  }
  return v;
}

}  // namespace

TEST_CASE("portable Int128: + - * / % and comparisons agree with __int128") {
  const auto v = samples();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t j = i; j < v.size(); j += 7) {
      const S a = v[i], b = v[j];
      const W wa = wide(a), wb = wide(b);
      REQUIRE(bits(wa + wb) == static_cast<U>(static_cast<U>(a) + static_cast<U>(b)));
      REQUIRE(bits(wa - wb) == static_cast<U>(static_cast<U>(a) - static_cast<U>(b)));
      REQUIRE(bits(wa * wb) == static_cast<U>(static_cast<U>(a) * static_cast<U>(b)));
      REQUIRE((wa < wb) == (a < b));
      REQUIRE((wa == wb) == (a == b));
      REQUIRE(bits(-wa) == static_cast<U>(-static_cast<U>(a)));
      const U ua = static_cast<U>(a), ub = static_cast<U>(b);
      REQUIRE((wideU(ua) < wideU(ub)) == (ua < ub));
      if (b != 0) {
        INFO("a=" << static_cast<double>(a) << " b=" << static_cast<double>(b));
        REQUIRE(bits(wa / wb) == static_cast<U>(a / b));
        REQUIRE(bits(wa % wb) == static_cast<U>(a % b));
        REQUIRE(bits(wideU(ua) / wideU(ub)) == ua / ub);
        REQUIRE(bits(wideU(ua) % wideU(ub)) == ua % ub);
      }
    }
  }
}

TEST_CASE("portable Int128: shifts and conversions agree with __int128") {
  for (const S a : samples()) {
    for (int s = 0; s < 128; ++s) {
      REQUIRE(bits(wide(a) << s) == static_cast<U>(static_cast<U>(a) << s));
      REQUIRE(bits(wide(a) >> s) == static_cast<U>(a >> s));
      REQUIRE(bits(wideU(static_cast<U>(a)) >> s) == static_cast<U>(a) >> s);
    }
    REQUIRE(static_cast<std::int64_t>(wide(a)) == static_cast<std::int64_t>(a));
  }
  REQUIRE(bits(W(std::int64_t{-5})) == static_cast<U>(S{-5}));
  REQUIRE(bits(WU(std::int64_t{-5})) == static_cast<U>(S{-5}));  // sign-extended, like the built-in
  REQUIRE(bits(W(std::uint64_t{UINT64_MAX})) == static_cast<U>(UINT64_MAX));
}

// The long-division path (a divisor that fits in 64 bits, a dividend that
// does not): Fixed32's quotients (|a| << 32 over a 63-bit divisor) and the
// square roots' n / r. Divisors with the top bit set or clear, one or two
// 32-bit digits, and dividends just below a multiple of the divisor, where a
// quotient digit's estimate needs its corrections.
TEST_CASE("portable Int128: division by a 64-bit divisor agrees with __int128") {
  std::mt19937_64 rng(29);
  for (int i = 0; i < 200000; ++i) {
    const int dLength = static_cast<int>(rng() % 64) + 1;
    std::uint64_t d = rng() >> (64 - dLength);
    if (d == 0) d = 1;
    U n;
    switch (i % 4) {
      case 0: n = static_cast<U>(rng()) << 64 | rng(); break;
      case 1: n = (static_cast<U>(rng() >> 1) << 32);  break;  // a Fixed32 dividend
      case 2: n = static_cast<U>(d) * (static_cast<U>(rng()) << (rng() % 64)) - 1; break;  // just below a multiple
      default: n = (static_cast<U>(d) << 64) - 1 - (rng() % 3); break;  // the largest quotients
    }
    INFO("n=" << static_cast<double>(n) << " d=" << d);
    REQUIRE(bits(wideU(n) / WU(d)) == n / d);
    REQUIRE(bits(wideU(n) % WU(d)) == n % d);
    const S sn = static_cast<S>(n >> 1), sd = (rng() & 1) ? -static_cast<S>(d) : static_cast<S>(d);
    REQUIRE(bits(wide(sn) / wide(sd)) == static_cast<U>(sn / sd));
    REQUIRE(bits(wide(-sn) % wide(sd)) == static_cast<U>(-sn % sd));
  }
}
