#include <catch2/catch.hpp>

#include "io/rate_limiter.hpp"

using lattice::io::RateLimiter;

TEST_CASE("The pacer lets bytes out at its rate and no faster", "[serial][pace]") {
  RateLimiter pacer(1000.0, 20.0, 0.0);  // 1000 B/s, bursts of 20 B
  CHECK(pacer.available(0.0) == 0);
  CHECK(pacer.available(0.010) == 10);
  pacer.consume(10);
  CHECK(pacer.available(0.010) == 0);
  CHECK(pacer.secondsUntil(5, 0.010) == Approx(0.005));
  // Simulate a sender that takes whatever is available every millisecond for one second.
  std::size_t sent = 10;
  for (int ms = 11; ms <= 1010; ++ms) {
    std::size_t n = pacer.available(ms / 1000.0);
    pacer.consume(n);
    sent += n;
  }
  CHECK(sent == Approx(1010).margin(2));
}

TEST_CASE("An idle pacer saves up at most one burst", "[serial][pace]") {
  RateLimiter pacer(1000.0, 20.0, 0.0);
  CHECK(pacer.available(60.0) == 20);  // a minute idle buys 20 bytes, not 60000
  CHECK(pacer.secondsUntil(500, 60.0) == 0.0);  // asks beyond the burst wait only for the burst
}
