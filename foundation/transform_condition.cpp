#include "foundation/transform_condition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lattice {

namespace {

// The largest eigenvalue of the symmetric 3x3 matrix a, by cyclic Jacobi
// rotations (accurate to a few ulps of the largest eigenvalue).
double largestEigenvalue(glm::dmat3 a) {
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-40 * diagonal) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        glm::dmat3 j(1.0);
        j[p][p] = c;
        j[q][q] = c;
        j[q][p] = s;  // column q, row p
        j[p][q] = -s;
        a = glm::transpose(j) * a * j;
      }
  }
  return std::max({a[0][0], a[1][1], a[2][2]});
}

// The largest singular value of m.
double largestSingularValue(const glm::dmat3& m) {
  return std::sqrt(std::max(0.0, largestEigenvalue(glm::transpose(m) * m)));
}

}  // namespace

SingularValueRange singularValueRange(const Mat4d& m) {
  const SingularValueRange singular{0.0, std::numeric_limits<double>::infinity()};
  const glm::dmat3 linear(m);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (!std::isfinite(linear[c][r])) return singular;
  const double det = glm::determinant(linear);
  if (det == 0.0 || !std::isfinite(det)) return singular;
  // Rotations times scales (every translate/rotate/scale, every scattered
  // lattice instance) have orthogonal columns: their lengths are the
  // singular values. Off-diagonal Gram entries of relative size e move the
  // smallest squared singular value by about e^2 kappa^2 of itself, nothing
  // at e = 1e-12 and kappa <= 1e6. This keeps a million instances cheap.
  const glm::dmat3 gram = glm::transpose(linear) * linear;
  bool orthogonal = true;
  for (int c = 0; c < 3; ++c)
    for (int r = c + 1; r < 3; ++r)
      orthogonal = orthogonal && std::abs(gram[c][r]) <= 1e-12 * std::sqrt(gram[c][c] * gram[r][r]);
  if (orthogonal) {
    const double lo = std::min({gram[0][0], gram[1][1], gram[2][2]});
    const double hi = std::max({gram[0][0], gram[1][1], gram[2][2]});
    return lo > 0.0 && std::isfinite(hi) ? SingularValueRange{std::sqrt(lo), std::sqrt(hi)} : singular;
  }
  // sigma_min(M) = 1 / sigma_max(M^-1): both largest singular values are
  // well conditioned, unlike the smallest eigenvalue of M^T M.
  const SingularValueRange range{1.0 / largestSingularValue(glm::inverse(linear)), largestSingularValue(linear)};
  return std::isfinite(range.largest) && range.smallest > 0.0 ? range : singular;
}

double conditionNumber(const Mat4d& m) {
  const SingularValueRange range = singularValueRange(m);
  return range.smallest > 0.0 ? range.largest / range.smallest : std::numeric_limits<double>::infinity();
}

namespace {

// 1e6 as "1e6" (limits are powers of ten; "{:.0e}" would say "1e+06").
std::string powerOfTen(double v) {
  const double e = std::round(std::log10(v));
  return std::pow(10.0, e) == v ? fmt::format("1e{}", e) : fmt::format("{:.3g}", v);
}

}  // namespace

std::string conditionProblem(const Mat4d& m, double limit, const std::string& arithmetic) {
  const double kappa = conditionNumber(m);
  if (kappa <= limit) return {};
  if (std::isinf(kappa))
    return "the transform is singular (a zero scale factor, or matrix columns that depend on each other); every "
           "scale factor must be non-zero and a matrix's columns independent";
  if (!arithmetic.empty())
    return fmt::format("the transform is too nearly singular for --arith {0}: its condition number (largest / "
                       "smallest scale factor) is {1:.3g}, above {2}, the most {0} can follow; use --arith double "
                       "(which follows up to {3}) or bring the scale factors closer to each other",
                       arithmetic, kappa, powerOfTen(limit), powerOfTen(kMaxTransformCondition));
  return fmt::format("the transform is nearly singular: its condition number (largest / smallest scale factor) "
                     "is {0:.3g}, above the limit {1}; keep every axis's scale factor within a factor {1} of the "
                     "others and a matrix's columns far from parallel (for a very thin solid, make the shape "
                     "itself thin instead of squashing it)",
                     kappa, powerOfTen(limit));
}

}  // namespace lattice
