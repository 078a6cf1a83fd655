#include "io/rate_limiter.hpp"

#include <algorithm>
#include <cmath>

namespace lattice::io {

RateLimiter::RateLimiter(double bytesPerSecond, double burst, double nowSeconds)
    : rate_(bytesPerSecond), burst_(std::max(1.0, burst)), credit_(0.0), last_(nowSeconds) {}

void RateLimiter::refill(double nowSeconds) {
  if (nowSeconds > last_) {
    // Capped, so a pause (a stall, a slow producer) does not buy a burst
    // faster than the line afterwards.
    credit_ = std::min(burst_, credit_ + (nowSeconds - last_) * rate_);
    last_ = nowSeconds;
  }
}

std::size_t RateLimiter::available(double nowSeconds) {
  refill(nowSeconds);
  return credit_ <= 0.0 ? 0 : static_cast<std::size_t>(std::floor(credit_));
}

void RateLimiter::consume(std::size_t bytes) { credit_ -= static_cast<double>(bytes); }

double RateLimiter::secondsUntil(std::size_t bytes, double nowSeconds) {
  refill(nowSeconds);
  double wanted = std::min(static_cast<double>(bytes), burst_);
  return credit_ >= wanted ? 0.0 : (wanted - credit_) / rate_;
}

}  // namespace lattice::io
