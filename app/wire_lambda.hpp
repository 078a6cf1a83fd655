#pragma once
// The rate-distortion lambda at which a picture's stream just fits a byte
// limit: the search step of the wire budget (app/wire_budget.hpp).
//
// Method: bytes fall as lambda grows, roughly as a power of it, so the
// search works on log bytes against log lambda. From a starting lambda (the
// one that fitted the setting tried before, which is usually near), each
// step aims at the limit along the slope measured between the last two
// attempts (a secant; a default slope before there are two), kept inside
// the bracket of the smallest fitting and the largest overflowing lambda
// found so far (the bracket's geometric middle when the secant leaves it).
// It stops once a fitting stream uses at least 1 - kFill of the limit, or
// after kMaxAttempts. Every attempt is the caller's real encoding, so a
// figure is never the model's. Before, a doubling ladder was bisected and
// then refined three times: eight encodings a setting, against three or
// four here for the same share of the bytes.
//
// Tunables: kFill (the share of the limit that may stay unused), the slope
// assumed before two attempts, kMaxAttempts, the lambda range.
#include <cstdint>
#include <functional>

#include "foundation/indexed_image.hpp"

namespace lattice::app {

inline constexpr double kLambdaFill = 0.01;   // stop once 99 % of the limit is used
inline constexpr int kLambdaMaxAttempts = 7;  // encodings a setting at most
inline constexpr double kLambdaMin = 1.0, kLambdaMax = 1.6e6;

// Encodes the picture smoothed at lambda into `out`, returning its bytes.
using LambdaAttempt = std::function<std::uint64_t(double lambda, IndexedImage& out)>;

struct LambdaFit {
  bool fits = false;       // some lambda within range gave a stream within the limit
  double lambda = 0;       // the smallest fitting lambda found; else the one of the smallest stream
  std::uint64_t bytes = 0;
  IndexedImage picture;    // its picture
  int attempts = 0;
};

LambdaFit fitLambda(const LambdaAttempt& attempt, std::uint64_t limit, double start);

}  // namespace lattice::app
