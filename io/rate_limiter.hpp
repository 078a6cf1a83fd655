#pragma once
// --pace: holds a byte stream to the speed of the line it pretends to be.
// A UART paces itself; a pty or a network bridge takes bytes as fast as we
// write them, which outruns an emulator that models the real terminal, or a
// terminal behind a bridge with a small buffer. A token bucket: credit grows
// at bytesPerSecond up to `burst` bytes, each byte sent spends one.
// Time is passed in (seconds on any steady clock) so tests need no sleeping.
#include <cstddef>

namespace lattice::io {

class RateLimiter {
 public:
  // bytesPerSecond > 0; burst >= 1 byte.
  RateLimiter(double bytesPerSecond, double burst, double nowSeconds);
  // Whole bytes that may go out at `now`.
  std::size_t available(double nowSeconds);
  void consume(std::size_t bytes);
  // Seconds from `now` until `bytes` (at most the burst) may go out.
  double secondsUntil(std::size_t bytes, double nowSeconds);
  double bytesPerSecond() const { return rate_; }

 private:
  void refill(double nowSeconds);

  double rate_;
  double burst_;
  double credit_;
  double last_;
};

}  // namespace lattice::io
