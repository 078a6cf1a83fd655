#pragma once
// The fixed-point (Fixed32) branch of render/solve/roots.hpp: solvePolynomial and
// evaluatePolynomial dispatch here when T = Fixed32. Integer arithmetic only
// (64-bit values, 128-bit products); docs/fixed-point.md has the method and
// its limits.
#include <span>

#include "foundation/fixed.hpp"

namespace lattice::fixed_roots {

// Real roots of c[0] + c[1] x + ... + c[size-1] x^(size-1), size <= 5, with
// the contract of solvePolynomial (ascending, NaN-free by construction).
// A root beyond the Q31.32 range comes back saturated (+-2^31: "infinitely
// far" to the renderer) instead of being dropped, so the sign walk of a
// caller between roots stays right.
int solve(const Fixed32* c, int size, Fixed32 roots[4]);

// p(x) evaluated in 128-bit Q32 and saturated once at the end, so a huge
// value keeps its sign (an intermediate that would overflow 128 bits is
// already far beyond the Q31.32 range and saturates with the right sign).
Fixed32 evaluate(std::span<const Fixed32> c, Fixed32 x);

}  // namespace lattice::fixed_roots
