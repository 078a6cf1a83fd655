#include "exporter/quartic_forms.hpp"

#include <algorithm>
#include <cmath>

#include "render/shapes/quartic_presets.hpp"

namespace lattice::exporter {

namespace {

double largestCoefficient(const QuarticPolynomial& f) {
  double m = 0;
  for (double c : f.a) m = std::max(m, std::abs(c));
  return m;
}

bool sameUpToTolerance(const QuarticPolynomial& a, const QuarticPolynomial& b) {
  const double scale = std::max(largestCoefficient(a), largestCoefficient(b));
  for (std::size_t n = 0; n < a.a.size(); ++n)
    if (std::abs(a.a[n] - b.a[n]) > kRelativeTolerance * scale) return false;
  return true;
}

QuarticForm quadricForm(const QuarticPolynomial& f) {
  QuarticForm q;
  q.kind = QuarticForm::Kind::Quadric;
  q.quadric = {f.coefficient(2, 0, 0), f.coefficient(0, 2, 0), f.coefficient(0, 0, 2),
               f.coefficient(1, 1, 0), f.coefficient(1, 0, 1), f.coefficient(0, 1, 1),
               f.coefficient(1, 0, 0), f.coefficient(0, 1, 0), f.coefficient(0, 0, 1),
               f.coefficient(0, 0, 0)};
  const auto& c = q.quadric;
  const double a = c[0];
  const double tol = kRelativeTolerance * largestCoefficient(f);
  const bool round = a > 0 && std::abs(c[1] - a) <= tol && std::abs(c[2] - a) <= tol;
  const bool noCross = std::abs(c[3]) <= tol && std::abs(c[4]) <= tol && std::abs(c[5]) <= tol;
  if (round && noCross) {
    // a |p - centre|^2 - a r^2 = a p.p + (G, H, I) . p + J
    const Vec3d centre = Vec3d(c[6], c[7], c[8]) * (-0.5 / a);
    const double r2 = glm::dot(centre, centre) - c[9] / a;
    if (r2 > 0) {
      q.kind = QuarticForm::Kind::Sphere;
      q.centre = centre;
      q.radius = std::sqrt(r2);
    }
  }
  return q;
}

QuarticForm torusForm(const QuarticPolynomial& f) {
  QuarticForm t;
  const double x4 = f.coefficient(4, 0, 0);
  if (!(x4 > 0)) return t;
  // torus(R, r) / (scale): x^2 coefficient 2 (R^2 - r^2) - 4 R^2, z^2 coefficient 2 (R^2 - r^2).
  const double z2 = f.coefficient(0, 0, 2) / x4, xx = f.coefficient(2, 0, 0) / x4;
  const double R2 = (z2 - xx) / 4, r2 = R2 - z2 / 2;
  if (!(R2 > 0 && r2 > 0)) return t;
  const double R = std::sqrt(R2), r = std::sqrt(r2);
  QuarticPolynomial rebuilt = torus(R, r).f;
  rebuilt *= x4 / rebuilt.coefficient(4, 0, 0);
  if (!sameUpToTolerance(rebuilt, f)) return t;
  t.kind = QuarticForm::Kind::Torus;
  t.major = R;
  t.minor = r;
  return t;
}

}  // namespace

QuarticForm classifyQuartic(const QuarticPolynomial& f) {
  const int degree = f.degree();
  if (degree == 1) {
    QuarticForm p;
    p.kind = QuarticForm::Kind::Plane;
    const Vec3d n(f.coefficient(1, 0, 0), f.coefficient(0, 1, 0), f.coefficient(0, 0, 1));
    const double length = glm::length(n);
    p.normal = n / length;
    p.offset = -f.coefficient(0, 0, 0) / length;
    return p;
  }
  if (degree == 2) return quadricForm(f);
  if (degree == 4) return torusForm(f);
  return {};
}

std::array<double, QuarticPolynomial::kTerms> povQuarticOrder(const QuarticPolynomial& f) {
  std::array<double, QuarticPolynomial::kTerms> out{};
  std::size_t n = 0;
  for (int i = 4; i >= 0; --i)
    for (int j = 4 - i; j >= 0; --j)
      for (int k = 4 - i - j; k >= 0; --k) out[n++] = f.coefficient(i, j, k);
  return out;
}

}  // namespace lattice::exporter
