#pragma once
// Real roots of polynomials of degree <= 4: the numerical heart of quartic
// ray intersection. Closed form (as the thesis asks), made robust: stable
// quadratic, stable cubic, a quartic solver in the spirit of Orellana &
// De Michele (ACM TOMS 1010), Newton polishing, and a bracketing fallback
// when coefficients span too many orders of magnitude.
//
// Contract (every function, T = float, double or Fixed32; fixed point has its
// own method, render/solve/roots_fixed.hpp):
// - coefficients are given lowest power first: c[0] + c[1] x + ... + c[n] x^n;
//   leading (highest) coefficients that are zero lower the degree.
// - returns the number of real roots written to `roots`, ascending. A root of
//   multiplicity m is reported once or m times, as far as it can be told
//   apart numerically; callers decide inside/outside from the sign of the
//   polynomial between roots, never by counting roots.
// - a polynomial that is identically zero, or a non-zero constant, has no
//   roots (returns 0). NaN or infinite coefficients give 0 roots.
#include <span>

#include "foundation/fixed.hpp"

namespace lattice {

template <typename T>
int solveQuadratic(const T c[3], T roots[2]);
template <typename T>
int solveCubic(const T c[4], T roots[3]);
template <typename T>
int solveQuartic(const T c[5], T roots[4]);

// Any degree 0..4 (coeffs.size() - 1), dispatching on the effective degree.
template <typename T>
int solvePolynomial(std::span<const T> coeffs, T roots[4]);

// Horner evaluation, lowest power first.
template <typename T>
T evaluatePolynomial(std::span<const T> coeffs, T x);

}  // namespace lattice
