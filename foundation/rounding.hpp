#pragma once
// Rounding to nearest, written once: an integer quotient, and a real value
// scaled onto integer steps. Every helper rounds a half away from zero (as
// std::round and std::lround do), so results do not depend on which one a
// caller picks.
//
// Method: roundedQuotient adds half the divisor to the magnitude before the
// truncating division and puts the sign back after, so -5/2 gives -3 as 5/2
// gives 3 (C++'s `/` alone truncates towards zero). scaledStep clamps before
// scaling, so NaN aside the result stays within the steps asked for.
#include <algorithm>
#include <cmath>

namespace lattice {

// num / den rounded to nearest, halves away from zero; den > 0.
template <class Int>
constexpr Int roundedQuotient(Int num, Int den) {
  return num >= 0 ? (num + den / 2) / den : -((-num + den / 2) / den);
}

// v clamped to [lo, hi], times scale, rounded to the nearest integer (the
// step of a quantized fraction or normal component, a colour level).
inline long scaledStep(double v, double lo, double hi, double scale) {
  return std::lround(std::clamp(v, lo, hi) * scale);
}

}  // namespace lattice
