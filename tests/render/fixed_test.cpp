#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "foundation/fixed.hpp"

using lattice::Fixed32;
using Lim = std::numeric_limits<Fixed32>;

TEST_CASE("fixed: conversions round to nearest and saturate") {
  CHECK(Fixed32(1.5).toDouble() == 1.5);
  CHECK(Fixed32(-2).toDouble() == -2.0);
  CHECK(Fixed32(0.1).toDouble() == Approx(0.1).epsilon(1e-9));
  CHECK(Fixed32(1e12) == Lim::max());
  CHECK(Fixed32(-1e12) == Lim::lowest());
  CHECK(Fixed32(std::nan("")).toDouble() == 0.0);
  CHECK(Fixed32(std::numeric_limits<double>::infinity()) == Lim::infinity());
  CHECK(static_cast<int>(Fixed32(-0.5)) == -1);  // floor
}

TEST_CASE("fixed: arithmetic matches double within one unit in the last place") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> value(-4.0e4, 4.0e4);
  const double ulp = std::ldexp(1.0, -32);
  for (int i = 0; i < 20000; ++i) {
    double a = value(rng), b = value(rng);
    Fixed32 fa(a), fb(b);
    double ea = fa.toDouble(), eb = fb.toDouble();  // the exactly represented operands
    CHECK(std::abs((fa + fb).toDouble() - (ea + eb)) <= ulp);
    CHECK(std::abs((fa - fb).toDouble() - (ea - eb)) <= ulp);
    CHECK(std::abs((fa * fb).toDouble() - ea * eb) <= std::abs(ea * eb) * 1e-15 + ulp);
    if (std::abs(eb) > 1e-3) {
      double q = ea / eb;
      CHECK(std::abs((fa / fb).toDouble() - q) <= std::abs(q) * 1e-15 + ulp);
    }
  }
}

TEST_CASE("fixed: overflow saturates instead of wrapping") {
  Fixed32 big(2.0e9);
  CHECK((big + big) == Lim::max());
  CHECK((-big - big) == Lim::lowest());
  CHECK((big * big) == Lim::max());
  CHECK((big * -big) == Lim::lowest());
  CHECK((big / Fixed32(1e-6)) == Lim::max());
  CHECK((Fixed32(3) / Fixed32(0)) == Lim::max());
  CHECK((Fixed32(-3) / Fixed32(0)) == Lim::lowest());
  CHECK((Fixed32(0) / Fixed32(0)).toDouble() == 0.0);
  CHECK((-Lim::lowest()) == Lim::max());  // symmetric range: negation is safe
  CHECK((big + big).saturated());
}

TEST_CASE("fixed: sqrt is correctly rounded") {
  CHECK(sqrt(Fixed32(4)).toDouble() == 2.0);
  CHECK(sqrt(Fixed32(-4)).toDouble() == 0.0);
  CHECK(sqrt(Fixed32(0)).toDouble() == 0.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> value(0.0, 2.0e9);
  const double ulp = std::ldexp(1.0, -32);
  for (int i = 0; i < 5000; ++i) {
    Fixed32 x(value(rng) * (i % 2 ? 1.0 : 1e-9));
    double exact = std::sqrt(x.toDouble());
    CHECK(std::abs(sqrt(x).toDouble() - exact) <= ulp * 0.5 + exact * 1e-16);
  }
  CHECK(sqrt(Lim::max()).toDouble() == Approx(std::sqrt(Lim::max().toDouble())).epsilon(1e-12));
}

TEST_CASE("fixed: ordering and infinity behave like numbers") {
  CHECK(Fixed32(1) < Fixed32(2));
  CHECK(Fixed32(-1) < Fixed32(0.5));
  CHECK(Lim::infinity() > Fixed32(1e9));
  CHECK(abs(Fixed32(-3.25)).toDouble() == 3.25);
}
