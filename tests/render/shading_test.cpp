// Eq. 2.3 against numbers worked out by hand.
#include <catch2/catch.hpp>

#include "render/shapes/quartic.hpp"
#include "render/scene/shading.hpp"
#include "render/shapes/quartic_presets.hpp"

using namespace lattice;

namespace {

const auto allVisible = [](std::size_t, const Vec3d&) { return true; };

// The lit point is the origin with normal +y; a light at (3, 4, 0) is at
// distance D = 5 in direction l = (0.6, 0.8, 0), so n . l = 0.8 and the mirror
// direction r = 2 (l . n) n - l = (-0.6, 0.8, 0).
LightingModel<double> oneLight(Vec3d intensity, double K, Material<double> m) {
  LightingModel<double> model;
  model.ambient = Vec3d(0.0);
  model.attenuationK = K;
  model.lights.push_back({Vec3d(3, 4, 0), intensity});
  model.materials.push_back(m);
  return model;
}

Material<double> material(double amb, double diff, double spec, double n) {
  return {Vec3d(amb), Vec3d(diff), Vec3d(spec), Vec3d(n)};
}

void requireColor(const Vec3d& c, double r, double g, double b) {
  INFO("got (" << c.r << ", " << c.g << ", " << c.b << "), expected (" << r << ", " << g << ", " << b << ")");
  REQUIRE(c.r == Approx(r).margin(1e-12));
  REQUIRE(c.g == Approx(g).margin(1e-12));
  REQUIRE(c.b == Approx(b).margin(1e-12));
}

const Vec3d kOrigin(0, 0, 0), kUp(0, 1, 0);

}  // namespace

TEST_CASE("lighting: ambient only is k_amb times I_amb per channel") {
  LightingModel<double> model;
  model.ambient = Vec3d(0.2, 0.5, 1.0);
  model.materials.push_back({Vec3d(0.5, 0.4, 0.2), Vec3d(0.9), Vec3d(0.9), Vec3d(5)});
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, allVisible), 0.1, 0.2, 0.2);
}

TEST_CASE("lighting: one light gives the diffuse term I_inc over D plus K times k_diff times n.l") {
  // K = 1: I / 6 = (1, 0.5, 0.2); times k_diff 0.5 and n . l 0.8.
  auto model = oneLight(Vec3d(6, 3, 1.2), 1.0, material(0, 0.5, 0, 1));
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 10, 0), 0, allVisible), 0.4, 0.2, 0.08);
}

TEST_CASE("lighting: Phong specular peaks at the mirror angle") {
  // K = 0, I = 5: the light delivers 5 / 5 = 1. k_diff = 0 isolates the
  // specular term k_spec (r . s)^n with s from the point towards the observer.
  auto model = oneLight(Vec3d(5), 0.0, material(0, 0, 0.3, 2));
  // Observer along r = (-0.6, 0.8, 0): r . s = 1, full k_spec.
  requireColor(shade(model, kOrigin, kUp, Vec3d(-6, 8, 0), 0, allVisible), 0.3, 0.3, 0.3);
  // Observer straight above: r . s = 0.8, 0.3 * 0.8^2 = 0.192.
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 3, 0), 0, allVisible), 0.192, 0.192, 0.192);
  // Observer on the light's own side, past the normal: r . s = (-0.6*0.6 + 0.8*0.8) = 0.28.
  requireColor(shade(model, kOrigin, kUp, Vec3d(3, 4, 0), 0, allVisible), 0.3 * 0.28 * 0.28, 0.3 * 0.28 * 0.28,
               0.3 * 0.28 * 0.28);
  // Grazing the other way (s = (1, 0, 0)): r . s < 0 contributes nothing.
  requireColor(shade(model, kOrigin, kUp, Vec3d(1, 0.0001, 0), 0, allVisible), 0, 0, 0);
}

TEST_CASE("lighting: each channel takes its own Phong exponent, channels that share one share its power") {
  // Observer straight above: r . s = 0.8. Exponents 1, 2, 1 and a channel
  // with no specular between two that share an exponent: 0.8, 0.64, 0.8 times
  // k_spec 0.5, 0.25 and 0.5 (the second channel's k_spec 0.5, the third 1).
  Material<double> m{Vec3d(0), Vec3d(0), Vec3d(0.5, 0.5, 1.0), Vec3d(1, 2, 1)};
  auto model = oneLight(Vec3d(5), 0.0, m);
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 3, 0), 0, allVisible), 0.4, 0.32, 0.8);
  m = {Vec3d(0), Vec3d(0), Vec3d(0.5, 0.0, 1.0), Vec3d(3, 1, 3)};
  model = oneLight(Vec3d(5), 0.0, m);
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 3, 0), 0, allVisible), 0.5 * 0.512, 0, 0.512);
  m = {Vec3d(0), Vec3d(0), Vec3d(1.0), Vec3d(2, 2, 3)};
  model = oneLight(Vec3d(5), 0.0, m);
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 3, 0), 0, allVisible), 0.64, 0.64, 0.512);
}

TEST_CASE("lighting: attenuation is 1 over D plus K") {
  auto model = oneLight(Vec3d(8), 3.0, material(0, 0.5, 0, 1));
  // D = 5, K = 3: 8 / 8 * 0.5 * 0.8.
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, allVisible), 0.4, 0.4, 0.4);
  // Twice as far, same direction: D = 10, 8 / 13 * 0.4.
  model.lights[0].position = Vec3d(6, 8, 0);
  const double v = 8.0 / 13.0 * 0.4;
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, allVisible), v, v, v);
}

TEST_CASE("lighting: lights behind the surface and shadowed lights are dropped") {
  auto model = oneLight(Vec3d(5), 0.0, material(0, 0.5, 0, 1));
  model.lights.push_back({Vec3d(0, 2, 0), Vec3d(2)});  // straight above: D = 2, n . l = 1 -> 0.5
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, allVisible), 0.4 + 0.5, 0.9, 0.9);
  // The visibility callback decides N_vs: drop light 0.
  auto onlySecond = [](std::size_t i, const Vec3d&) { return i == 1; };
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, onlySecond), 0.5, 0.5, 0.5);
  // A light under the surface adds nothing, whatever the callback says.
  model.lights[1].position = Vec3d(0, -2, 0);
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, allVisible), 0.4, 0.4, 0.4);
}

TEST_CASE("lighting: the normal is turned towards the observer and results clamp to 1") {
  auto model = oneLight(Vec3d(5), 0.0, material(0, 0.5, 0, 1));
  // The same surface seen with its normal reported pointing away from the eye.
  requireColor(shade(model, kOrigin, -kUp, Vec3d(0, 1, 0), 0, allVisible), 0.4, 0.4, 0.4);
  model.lights[0].intensity = Vec3d(100, 1, 0);
  requireColor(shade(model, kOrigin, kUp, Vec3d(0, 1, 0), 0, allVisible), 1.0, 0.08, 0.0);
}

TEST_CASE("lighting: shadow rays stop at a real occluder and not at the light's far side") {
  // A unit sphere at (0, 2, 0) sits between the origin and a light at (0, 4, 0).
  Mat4d at(1.0);
  at[3] = glm::dvec4(0, 2, 0, 1);
  auto sphere1 = makeQuarticLeaf<double>(sphere(1.0).f, sphere(1.0).bounds, at, 0);
  REQUIRE(inShadow<double>(*sphere1, kOrigin, kUp, Vec3d(0, 4, 0)));
  // A light between the point and the sphere is not shadowed by it.
  REQUIRE_FALSE(inShadow<double>(*sphere1, kOrigin, kUp, Vec3d(0, 0.5, 0)));
  // The sphere's own top point, lit from above, does not shadow itself.
  REQUIRE_FALSE(inShadow<double>(*sphere1, Vec3d(0, 3, 0), kUp, Vec3d(0, 6, 0)));
  // Same for float, whose roots are rougher (the offset scales with T).
  auto sphere1f = makeQuarticLeaf<float>(sphere(1.0).f, sphere(1.0).bounds, at, 0);
  REQUIRE_FALSE(inShadow<float>(*sphere1f, Vec3<float>(0.6f, 2.8f, 0), glm::normalize(Vec3<float>(0.6f, 0.8f, 0)),
                                Vec3<float>(3, 6, 0)));
}
