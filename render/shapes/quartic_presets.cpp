// Quartic presets. Each polynomial is written with unit-scale coefficients
// (divided through by the shape's size where that keeps |grad f| near 1 at
// the surface), which keeps the ray polynomials well conditioned.
#include "render/shapes/quartic_presets.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "foundation/error.hpp"

namespace lattice {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void requirePositive(const char* shape, const char* name, double v) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw Error(ErrorKind::Input,
                fmt::format("{}: {} must be a positive finite number, got {}", shape, name, v));
}

using P = QuarticPolynomial;

P sq(const P& p) { return p * p; }

Bounds<double> box(double x, double y, double z) { return {Vec3d(-x, -y, -z), Vec3d(x, y, z)}; }

}  // namespace

QuarticShape halfSpace(const Vec3d& normal, double offset) {
  if (!std::isfinite(offset) || !std::isfinite(normal.x) || !std::isfinite(normal.y) || !std::isfinite(normal.z))
    throw Error(ErrorKind::Input, "half-space: normal and offset must be finite");
  if (normal == Vec3d(0))
    throw Error(ErrorKind::Input, "half-space: the normal is zero; give the outward direction, e.g. [0, 0, 1]");
  QuarticShape s{P::x() * normal.x + P::y() * normal.y + P::z() * normal.z - P::constant(offset), Bounds<double>::infinite()};
  // An axis-aligned normal cuts the box on one side of one axis.
  int nonZero = 0, axis = 0;
  for (int a = 0; a < 3; ++a)
    if (normal[a] != 0.0) {
      ++nonZero;
      axis = a;
    }
  if (nonZero == 1) {
    double limit = offset / normal[axis];
    if (normal[axis] > 0)
      s.bounds.hi[axis] = limit;
    else
      s.bounds.lo[axis] = limit;
  }
  return s;
}

QuarticShape sphere(double r) {
  requirePositive("sphere", "radius", r);
  // (x^2 + y^2 + z^2) / r - r: the same surface, gradient of length 2 on it.
  return {(sq(P::x()) + sq(P::y()) + sq(P::z())) * (1.0 / r) - P::constant(r), box(r, r, r)};
}

QuarticShape ellipsoid(double rx, double ry, double rz) {
  requirePositive("ellipsoid", "rx", rx);
  requirePositive("ellipsoid", "ry", ry);
  requirePositive("ellipsoid", "rz", rz);
  return {sq(P::x() * (1.0 / rx)) + sq(P::y() * (1.0 / ry)) + sq(P::z() * (1.0 / rz)) - P::constant(1.0),
          box(rx, ry, rz)};
}

QuarticShape cylinder(double r) {
  requirePositive("cylinder", "radius", r);
  return {(sq(P::x()) + sq(P::y())) * (1.0 / r) - P::constant(r), box(r, r, kInf)};
}

QuarticShape cone(double slope) {
  requirePositive("cone", "slope", slope);
  return {sq(P::x()) + sq(P::y()) - sq(P::z() * slope), Bounds<double>::infinite()};
}

QuarticShape paraboloid(double k) {
  requirePositive("paraboloid", "k", k);
  Bounds<double> b = Bounds<double>::infinite();
  b.lo.z = 0.0;  // x^2 + y^2 < k z needs z > 0
  return {(sq(P::x()) + sq(P::y())) * (1.0 / k) - P::z(), b};
}

QuarticShape hyperboloid(double a, double c, bool oneSheet) {
  requirePositive("hyperboloid", "a", a);
  requirePositive("hyperboloid", "c", c);
  P q = (sq(P::x()) + sq(P::y())) * (1.0 / (a * a)) - sq(P::z()) * (1.0 / (c * c));
  return {oneSheet ? q - P::constant(1.0) : q + P::constant(1.0), Bounds<double>::infinite()};
}

QuarticShape torus(double R, double r) {
  requirePositive("torus", "major radius R", R);
  requirePositive("torus", "tube radius r", r);
  P rho2 = sq(P::x()) + sq(P::y());
  P d = rho2 + sq(P::z()) + P::constant(R * R - r * r);
  // Divided by R^2 so the coefficients stay of the order of the shape's size.
  P f = (sq(d) - rho2 * (4.0 * R * R)) * (1.0 / (R * R));
  double e = R + r;
  return {f, box(e, e, r)};
}

}  // namespace lattice
