// A quartic leaf's polynomial is recognised as the closed form it is, so a
// peer renderer traces it with its own routine (exporter/quartic_forms.hpp).
#include <catch2/catch.hpp>

#include "exporter/quartic_forms.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;
using lattice::exporter::classifyQuartic;
using Kind = lattice::exporter::QuarticForm::Kind;
using P = QuarticPolynomial;

TEST_CASE("exporter: half-spaces are planes with a unit normal") {
  const auto form = classifyQuartic(halfSpace(Vec3d(0, 2, 0), -1.2).f);
  REQUIRE(form.kind == Kind::Plane);
  CHECK(form.normal.y == Approx(1.0));
  CHECK(form.normal.x == 0.0);
  CHECK(form.offset == Approx(-0.6));  // 2 y < -1.2  <=>  y < -0.6
}

TEST_CASE("exporter: spheres, centred or not, are spheres and other quadrics stay quadrics") {
  auto form = classifyQuartic(sphere(1.5).f);
  REQUIRE(form.kind == Kind::Sphere);
  CHECK(form.radius == Approx(1.5));
  CHECK(glm::length(form.centre) == Approx(0.0).margin(1e-12));
  // (x - 1)^2 + (y + 2)^2 + z^2 - 4, scaled by 3.
  const P off = ((P::x() - P::constant(1)) * (P::x() - P::constant(1)) + (P::y() + P::constant(2)) *
                 (P::y() + P::constant(2)) + P::z() * P::z() - P::constant(4)) * 3.0;
  form = classifyQuartic(off);
  REQUIRE(form.kind == Kind::Sphere);
  CHECK(form.centre.x == Approx(1.0));
  CHECK(form.centre.y == Approx(-2.0));
  CHECK(form.radius == Approx(2.0));

  form = classifyQuartic(cylinder(0.42).f);
  REQUIRE(form.kind == Kind::Quadric);
  CHECK(form.quadric[2] == 0.0);  // no z^2 term
  CHECK(form.quadric[9] == Approx(-0.42));
  CHECK(classifyQuartic(ellipsoid(1, 2, 3).f).kind == Kind::Quadric);
  CHECK(classifyQuartic(cone(0.5).f).kind == Kind::Quadric);
}

TEST_CASE("exporter: the torus preset is a torus at any positive scale and other quartics are general") {
  auto form = classifyQuartic(torus(1.0, 0.35).f * 3.0);
  REQUIRE(form.kind == Kind::Torus);
  CHECK(form.major == Approx(1.0));
  CHECK(form.minor == Approx(0.35));
  // x^4 + y^4 + z^4 - 1: degree 4 but no torus.
  const P cube = P::x() * P::x() * P::x() * P::x() + P::y() * P::y() * P::y() * P::y() +
                 P::z() * P::z() * P::z() * P::z() - P::constant(1);
  CHECK(classifyQuartic(cube).kind == Kind::General);
  // A torus moved off its centre is no torus about z.
  P shifted = torus(1.0, 0.35).f;
  shifted.addTerm(0.1, 1, 0, 0);
  CHECK(classifyQuartic(shifted).kind == Kind::General);
}

TEST_CASE("exporter: POV-Ray's quartic order runs x^4, x^3 y, x^3 z, ..., z, 1") {
  P f;
  f.addTerm(1, 4, 0, 0).addTerm(2, 3, 1, 0).addTerm(3, 3, 0, 1).addTerm(4, 2, 0, 0).addTerm(5, 0, 0, 1);
  f.addTerm(6, 0, 0, 0);
  const auto order = lattice::exporter::povQuarticOrder(f);
  CHECK(order[0] == 1);
  CHECK(order[1] == 2);
  CHECK(order[2] == 3);
  CHECK(order[9] == 4);   // x^2 is A10
  CHECK(order[33] == 5);  // z is A34
  CHECK(order[34] == 6);  // the constant last
}
