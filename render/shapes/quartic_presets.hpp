#pragma once
// Named quartic presets (thesis 3.2.1: half-spaces, spheres, ellipsoids,
// paraboloids, hyperboloids, toroids are all quartics). Each comes with an
// object-space box that contains the solid (infinite where the solid is).
// Axes: shapes with an axis of symmetry use z.
#include "render/shapes/quartic_shape.hpp"

namespace lattice {

// Errors: lattice::Error (Input) for non-positive radii/semi-axes, a zero
// normal or non-finite parameters, naming the parameter.

// f = normal . p - offset: the solid is normal . p < offset. The box is
// infinite except along an axis-aligned normal.
QuarticShape halfSpace(const Vec3d& normal, double offset);
// x^2 + y^2 + z^2 < r^2.
QuarticShape sphere(double r);
// (x/rx)^2 + (y/ry)^2 + (z/rz)^2 < 1.
QuarticShape ellipsoid(double rx, double ry, double rz);
// x^2 + y^2 < r^2, infinite along z.
QuarticShape cylinder(double r);
// x^2 + y^2 < (slope z)^2: a double cone around z with its apex at the origin.
QuarticShape cone(double slope);
// x^2 + y^2 < k z (k > 0): opens towards +z, vertex at the origin.
QuarticShape paraboloid(double k);
// oneSheet: (x^2 + y^2)/a^2 - z^2/c^2 < 1 (the solid around the waist);
// two sheets: (x^2 + y^2)/a^2 - z^2/c^2 < -1 (the two solid caps' insides).
QuarticShape hyperboloid(double a, double c, bool oneSheet);
// (x^2 + y^2 + z^2 + R^2 - r^2)^2 < 4 R^2 (x^2 + y^2): a ring around z,
// tube radius r, centre-line radius R (R > r keeps the hole open).
QuarticShape torus(double R, double r);

}  // namespace lattice
