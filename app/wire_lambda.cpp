// The secant search of app/wire_lambda.hpp.
#include "app/wire_lambda.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace lattice::app {
namespace {

constexpr double kDefaultSlope = -0.6;  // d log bytes / d log lambda before two attempts say otherwise

struct Point {
  double lambda = 0;
  std::uint64_t bytes = 0;
};

}  // namespace

LambdaFit fitLambda(const LambdaAttempt& attempt, std::uint64_t limit, double start) {
  LambdaFit fit;
  std::optional<Point> over;  // the largest lambda whose stream was too long
  std::optional<Point> last, previous;
  IndexedImage trial;
  // Aim a little inside the limit, so a step that lands close still fits.
  const double target = double(limit) * (1.0 - kLambdaFill / 2);
  double lambda = std::clamp(start, kLambdaMin, kLambdaMax);
  for (int i = 0; i < kLambdaMaxAttempts; ++i) {
    const std::uint64_t bytes = attempt(lambda, trial);
    ++fit.attempts;
    if (bytes <= limit) {
      if (!fit.fits || lambda < fit.lambda) {
        fit.fits = true, fit.lambda = lambda, fit.bytes = bytes;
        std::swap(fit.picture, trial);
      }
      if (double(bytes) >= double(limit) * (1.0 - kLambdaFill)) break;
    } else {
      if (!over || lambda > over->lambda) over = Point{lambda, bytes};
      if (!fit.fits && (fit.bytes == 0 || bytes < fit.bytes)) {  // the smallest stream, while nothing fits
        fit.lambda = lambda, fit.bytes = bytes;
        std::swap(fit.picture, trial);
      }
      if (!fit.fits && lambda >= kLambdaMax) break;  // even the coarsest is too long
    }
    previous = last;
    last = Point{lambda, bytes};
    double slope = kDefaultSlope;
    if (previous && previous->bytes != last->bytes && previous->lambda != last->lambda)
      slope = std::log(double(last->bytes) / double(previous->bytes)) / std::log(last->lambda / previous->lambda);
    slope = std::clamp(slope, -4.0, -0.05);  // bytes never grow with lambda; a flat stretch must not send it away
    double next = lambda * std::pow(target / double(std::max<std::uint64_t>(bytes, 1)), 1.0 / slope);
    // Inside the bracket: above the largest overflowing lambda, below the smallest fitting one.
    const double low = over ? over->lambda : kLambdaMin, high = fit.fits ? fit.lambda : kLambdaMax;
    if (!(next > low && next < high)) next = over && fit.fits ? std::sqrt(low * high) : std::clamp(next, low, high);
    if (fit.fits && over && high / low < 1.01) break;  // the bracket is closed: nothing between to find
    if (next == lambda) break;
    lambda = next;
  }
  return fit;
}

}  // namespace lattice::app
