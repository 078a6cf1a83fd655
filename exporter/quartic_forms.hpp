#pragma once
// Which closed form a quartic leaf's polynomial is, so a peer renderer can
// use its own routine for it (POV-Ray's plane, sphere, quadric, torus;
// Embree's sphere) instead of a general quartic solver.
//
// Method: read off the coefficients. Degree 1 is a half-space; degree 2 is a
// quadric, and a sphere when its squares are equal and it has no cross
// terms; degree 4 is a torus about z when the torus rebuilt from its x^2 and
// z^2 coefficients (render/shapes/quartic_presets.hpp) has the same 35 coefficients to
// kRelativeTolerance of the largest. Anything else is General. Scaling f by
// a positive number changes neither the solid nor the answer.
#include <array>

#include "render/shapes/quartic.hpp"

namespace lattice::exporter {

struct QuarticForm {
  enum class Kind { Plane, Sphere, Quadric, Torus, General };
  Kind kind = Kind::General;
  Vec3d normal{0.0};  // Plane: the solid is normal . p < offset, |normal| = 1
  double offset = 0;
  Vec3d centre{0.0};  // Sphere
  double radius = 0;
  // Quadric: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J < 0,
  // in that order (POV-Ray's `quadric` order).
  std::array<double, 10> quadric{};
  double major = 0;  // Torus about z, centred at the origin
  double minor = 0;
};

inline constexpr double kRelativeTolerance = 1e-9;

QuarticForm classifyQuartic(const QuarticPolynomial& f);

// The 35 coefficients in POV-Ray's `quartic` order: x^4, x^3 y, x^3 z, x^3,
// x^2 y^2, ... (i from 4 down, then j, then k), the constant last.
std::array<double, QuarticPolynomial::kTerms> povQuarticOrder(const QuarticPolynomial& f);

}  // namespace lattice::exporter
