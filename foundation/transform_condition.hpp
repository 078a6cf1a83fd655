#pragma once
// How close an affine transform is to singular, and how close the renderer
// accepts (docs/stability.md, "Nearly singular transforms").
//
// A transform whose linear part squashes one direction much more than
// another makes world -> object (used by every ray) amplify rounding by its
// condition number kappa = sigma_max / sigma_min: double keeps about
// 16 - log10(kappa) digits, float 7 - log10(kappa). Measured on a sphere
// flattened or sheared to kappa (tests/render/extremes_test.cpp): float
// misses hits 1..6 % inside the solid from kappa 1e5, double from 1e8, Q31.32
// from 1e7..1e8. So scene files may use kappa <= 1e6 (double then keeps 10
// digits), and --arith float refuses more than 1e4 when the scene is built.
#include <cmath>
#include <string>
#include <type_traits>

#include "foundation/error.hpp"
#include "foundation/vec.hpp"

namespace lattice {

// The smallest and largest singular values of the 3x3 linear part of m: how
// much it shrinks and stretches lengths at most. {0, inf} when it is
// singular or has a non-finite entry.
struct SingularValueRange {
  double smallest = 0.0;
  double largest = 0.0;
};
SingularValueRange singularValueRange(const Mat4d& m);

// sigma_max / sigma_min of the 3x3 linear part of m (the 2-norm condition
// number); +inf when it is singular or has a non-finite entry.
double conditionNumber(const Mat4d& m);

// The largest condition number a scene file may use (checked at load).
inline constexpr double kMaxTransformCondition = 1e6;

// The largest condition number the arithmetic T follows.
template <typename T>
constexpr double maxTransformCondition() {
  return std::is_same_v<T, float> ? 1e4 : kMaxTransformCondition;
}

// Empty when m's condition number is at most `limit`; otherwise a sentence
// saying what is wrong with the transform and how to fix it. `arithmetic`
// names the number type whose limit it is ("" for the scene-file limit).
std::string conditionProblem(const Mat4d& m, double limit, const std::string& arithmetic = {});

// The same for the arithmetic T.
template <typename T>
std::string conditionProblemFor(const Mat4d& m) {
  return conditionProblem(m, maxTransformCondition<T>(), std::is_same_v<T, float> ? "float" : "");
}

// Refuses, as lattice::Error (Input) naming `what` ("quartic", "capsule",
// "instance"), a transform a leaf cannot follow in T: a non-finite entry or a
// condition number beyond T's limit. Every leaf refuses alike, so a scene
// fails the same way in every arithmetic.
template <typename T>
void checkLeafTransform(const Mat4d& m, const std::string& what) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r]))
        throw Error(ErrorKind::Input, what + " transform has a non-finite entry: check the scene's transforms");
  const std::string problem = conditionProblemFor<T>(m);
  if (!problem.empty()) throw Error(ErrorKind::Input, what + ": " + problem);
}

}  // namespace lattice
