// Numerical stability at the extremes, for each arithmetic (float, double,
// Fixed32): objects at 1e-3 and 1e4 units, node transforms scaling by 1e-4
// and 1e4, rays grazing a sphere and a torus, a camera inside a solid, and
// nearly singular transforms. Each case is compared with an exact (long
// double) or double-precision reference against a stated bound; the figures
// measured and the bounds are tabled in docs/stability.md (print them with
// LATTICE_PRINT_MEASUREMENTS=1, see tests/render/extremes_support.hpp).
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "render/shapes/csg.hpp"
#include "render/shapes/quartic.hpp"
#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "foundation/transform_condition.hpp"
#include "tests/render/extremes_support.hpp"
#include "tests/render/fixed_support.hpp"
#include "tests/render/scene_test_util.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::testing;

namespace {

constexpr int kSide = 48;  // image side of the scene comparisons

RenderSettings settings(int side = kSide) {
  RenderSettings s;
  s.width = side;
  s.height = side;
  s.threads = 2;
  return s;
}

// A sphere or a torus over a floor, lit by one light, every length scaled by
// k: either written into the shape's own sizes (viaScale false) or as a
// `scale = k` key on unit-sized objects. K = 0 and a light intensity scaled
// by k keep eq. 2.3's I / (D + K) - and so the picture - independent of k.
std::string scaledScene(double k, const std::string& object, bool viaScale) {
  const auto at = [&](double x, double y, double z) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", x * k, y * k, z * k); };
  const double size = viaScale ? 1.0 : k;
  const std::string scaleKey = viaScale ? fmt::format("scale = {:.17g}\n", k) : "";
  std::string text = fmt::format(
      "[options]\nwidth = {}\nheight = {}\nK = 0\nbackground = [0.1, 0.2, 0.3]\n"
      "[camera]\ntype = \"look_at\"\neye = {}\ntarget = [0.0, 0.0, 0.0]\nfov = 40\n"
      "[[lights]]\nposition = {}\nintensity = {:.17g}\n",
      kSide, kSide, at(0.6, 2.5, -4.5), at(3, 6, -4), 8 * k);
  if (object == "sphere")
    text += fmt::format("[[objects]]\ntype = \"sphere\"\nradius = {:.17g}\n", size);
  else
    text += fmt::format("[[objects]]\ntype = \"torus\"\nmajor = {:.17g}\nminor = {:.17g}\n"
                        "rotate = {{ axis = [1.0, 0.0, 0.0], degrees = 70.0 }}\n",
                        size, 0.35 * size);
  text += scaleKey;
  text += fmt::format("[[objects]]\ntype = \"half_space\"\nnormal = [0.0, 1.0, 0.0]\noffset = {:.17g}\n", -size);
  return text + scaleKey;
}

struct SceneAgreement {
  int rays = 0, hitMissDisagreements = 0;
  double worstRelativeT = 0, worstNormalAngle = 0;  // over rays both hit
  FixedVsDouble image;
};

// Every primary ray of the scene scaled by k, traced in T, against the same
// ray of the unit scene traced in double (t scales with k, normals not), and
// the rendered images (shading, shadows) against each other.
template <typename T>
SceneAgreement compareWithUnitScene(double k, const std::string& object, bool viaScale) {
  const SceneDesc unit = parseScene(scaledScene(1.0, object, false), "unit.toml");
  const SceneDesc scaled = parseScene(scaledScene(k, object, viaScale), "scaled.toml");
  Renderer<double> reference(unit, settings());
  Renderer<T> renderer(scaled, settings());
  SceneAgreement a;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      Hit<double> expected;
      Hit<T> got;
      const bool e = reference.root().firstHit(reference.camera().primaryRay(x, y), 0.0, INFINITY, expected);
      const bool g = renderer.root().firstHit(renderer.camera().primaryRay(x, y), T(0),
                                              std::numeric_limits<T>::infinity(), got);
      ++a.rays;
      if (e != g) {
        ++a.hitMissDisagreements;
        continue;
      }
      if (!e) continue;
      REQUIRE(lattice::finite(got.t));
      a.worstRelativeT =
          std::max(a.worstRelativeT, std::abs(static_cast<double>(got.t) / k - expected.t) / expected.t);
      a.worstNormalAngle = std::max(a.worstNormalAngle, angleBetween(toDouble(got.normal), expected.normal));
    }
  a.image = compareRenders(renderImage(renderer), renderImage(reference));
  return a;
}

template <typename T>
void checkScaledScene(double k, const std::string& object, bool viaScale) {
  const std::string what = fmt::format("{} {} {} {:g}", arithmeticName<T>(), object,
                                       viaScale ? "scale key" : "size", k);
  INFO(what);
  const SceneAgreement a = compareWithUnitScene<T>(k, object, viaScale);
  // Measured (docs/stability.md): float <= 1.7e-6 relative in t and 2.7e-5 rad
  // in the normal at any scale; double <= 5e-15 and 2e-8; Q31.32 at 1e-4 units
  // 2e-6 and 2.9e-5 (its resolution 2^-32 is 2.3e-6 of 1e-4), elsewhere <= 1e-6
  // and 1.3e-5. No ray changes between hit and miss.
  const double tBound = bound<T>(1e-5, 1e-13, 1e-5);
  const double angleBound = bound<T>(2e-4, 1e-10, 2e-4);
  reportMeasure(what + ": relative t error", a.worstRelativeT, tBound);
  reportMeasure(what + ": normal angle (rad)", a.worstNormalAngle, angleBound);
  reportMeasure(what + ": image PSNR (dB) vs unit scene in double", a.image.psnr, 35.0);
  CHECK(a.hitMissDisagreements == 0);
  CHECK(a.worstRelativeT <= tBound);
  CHECK(a.worstNormalAngle <= angleBound);
  // Shading adds shadow rays, lifted off the surface in proportion to the
  // scene (render/scene/shading.hpp): the pictures agree to within a few pixels.
  CHECK(a.image.psnr > 35.0);
  CHECK(a.image.farFraction < 0.005);
}

// A sphere and a torus (unit sizes) placed off the axes, for ray-level tests.
const Mat4d kPlace = glm::translate(Mat4d(1.0), Vec3d(0.3, -0.2, 0.5)) *
                     glm::rotate(Mat4d(1.0), 0.7, glm::normalize(Vec3d(1, 2, 3)));
constexpr double kMajor = 1.0, kMinor = 0.35;

}  // namespace

TEMPLATE_TEST_CASE("extremes: a sphere and a torus of 1e-3 and 1e4 units render like the unit scene", "[extremes]",
                   float, double, Fixed32) {
  for (const char* object : {"sphere", "torus"})
    for (double k : {1e-3, 1e4}) checkScaledScene<TestType>(k, object, false);
}

TEMPLATE_TEST_CASE("extremes: node transforms scaling by 1e-4 and 1e4 render like the unit scene", "[extremes]",
                   float, double, Fixed32) {
  for (const char* object : {"sphere", "torus"})
    for (double k : {1e-4, 1e4}) checkScaledScene<TestType>(k, object, true);
}

TEMPLATE_TEST_CASE("extremes: rays grazing a sphere and a torus agree with the exact tangent", "[extremes]", float,
                   double, Fixed32) {
  using T = TestType;
  // Rays pass the tangent point at a signed distance delta (in units of the
  // shape's size; negative dips into the solid), for delta from 1e-10 to 1e-1
  // each side and 0. The exact answer is for the ray as T holds it (rounded),
  // in long double. T may decide either way within its resolution of the
  // tangent, must agree beyond it, must not flicker as delta sweeps, and a
  // near-tangent hit must lie near the tangent point.
  const double clearanceBound = bound<T>(5e-7, 1e-14, 5e-9);
  const double tBound = bound<T>(2e-3, 1e-6, 1e-4);
  const QuarticShape sphereShape = sphere(1.0), torusShape = torus(kMajor, kMinor);
  const Mat4d toLocal = glm::inverse(kPlace);
  std::vector<double> deltas{0.0};
  for (double e = -10; e <= -1; e += 0.25) {
    deltas.push_back(std::pow(10.0, e));
    deltas.push_back(-std::pow(10.0, e));
  }
  std::sort(deltas.begin(), deltas.end());
  struct Case {
    const char* name;
    const QuarticShape& shape;
    Vec3d origin, direction, offsetAxis;
    double tTangent;
  };
  // The torus lies around z: "rim" grazes its outer equator from the side,
  // "top" passes over the tube, touching it at two points (two double roots).
  const Case cases[] = {
      {"sphere", sphereShape, Vec3d(-5, 1, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), 5.0},
      {"torus rim", torusShape, Vec3d(kMajor + kMinor, -5, 0), Vec3d(0, 1, 0), Vec3d(1, 0, 0), 5.0},
      {"torus top", torusShape, Vec3d(-5, 0, kMinor), Vec3d(1, 0, 0), Vec3d(0, 0, 1), 5.0 - kMajor},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const auto leaf = makeQuarticLeaf<T>(c.shape.f, c.shape.bounds, kPlace, 0);
    const bool isSphere = &c.shape == &sphereShape;
    const auto f = [&](const RealVec& p) {
      return isSphere ? sphereFunction(p, 1) : torusFunction(p, kMajor, kMinor);
    };
    double worstDisagreement = 0, worstT = 0;
    int flips = 0;
    bool previousHit = true;  // the sweep starts deep inside the tangent (delta = -0.1)
    for (double delta : deltas) {
      INFO("delta " << delta);
      const Ray<double> local{c.origin + c.offsetAxis * delta, c.direction};
      const Ray<T> ray{Vec3<T>(transformPoint(kPlace, local.origin)), Vec3<T>(transformDirection(kPlace, local.direction))};
      const ExactGraze exact = exactGraze(f, exactRay(ray, toLocal), c.tTangent, 1.0L);
      Hit<T> hit;
      const T inf = std::numeric_limits<T>::infinity();
      const bool got = leaf->firstHit(ray, T(0), inf, hit);
      CHECK(leaf->anyHit(ray, T(0), inf) == got);  // shadow rays see what primary rays see
      if (got != exact.hit) worstDisagreement = std::max(worstDisagreement, double(std::abs(exact.clearance)));
      if (got != previousHit) ++flips;
      previousHit = got;
      if (!got) continue;
      REQUIRE(lattice::finite(hit.t));
      REQUIRE(std::abs(glm::length(toDouble(hit.normal)) - 1.0) < 1e-3);
      // A hit the exact ray does not have lies where the tangent is.
      const double expectedT = double(exact.hit ? exact.enter : exact.tClosest);
      worstT = std::max(worstT, std::abs(static_cast<double>(hit.t) - expectedT));
    }
    const std::string what = fmt::format("{} grazing {}", arithmeticName<T>(), c.name);
    reportMeasure(what + ": largest |clearance| of a hit/miss disagreement", worstDisagreement, clearanceBound);
    reportMeasure(what + ": worst near-tangent t error", worstT, tBound);
    CHECK(worstDisagreement <= clearanceBound);
    CHECK(worstT <= tBound);
    CHECK(flips == 1);  // hit ... hit miss ... miss
  }
}

namespace {

// The first crossing at t > 0 of a ray that starts inside f < 0: march out in
// steps of `step` until f >= 0, then bisect (long double).
template <typename F>
Real exactExit(F f, const ExactRay& ray, Real step) {
  Real inside = 0, outside = step;
  while (f(ray.at(outside)) < 0) {
    inside = outside;
    outside += step;
  }
  for (int i = 0; i < 200; ++i) {
    const Real m = (inside + outside) / 2;
    (f(ray.at(m)) < 0 ? inside : outside) = m;
  }
  return (inside + outside) / 2;
}

struct InsideAgreement {
  int rays = 0, misses = 0, wrongSide = 0;
  // |t - t_exact| |direction|: the distance along the ray, in units of the
  // solids' size (1). Relative to t it would blame the arithmetic for the
  // eye's own rounding when the surface is 1e-3 away.
  double worstDistance = 0, worstNormalAngle = 0;
};

// Rays from `eye` (world) in `count` random directions: the first crossing
// must be the solid's surface seen from inside (the normal, pointing out of
// the solid, faces along the ray) at the exact t.
template <typename T, typename ExactT, typename ExactNormal>
InsideAgreement fromInside(const Primitive<T>& solid, const Vec3d& eye, ExactT exactT, ExactNormal exactNormal,
                           int count = 300) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  InsideAgreement a;
  for (int i = 0; i < count; ++i) {
    const Vec3d d = glm::normalize(Vec3d(g(rng), g(rng), g(rng))) * (0.5 + i % 3);  // not unit: t scales
    const Ray<T> ray{Vec3<T>(eye), Vec3<T>(d)};
    ++a.rays;
    Hit<T> hit;
    if (!solid.firstHit(ray, T(0), std::numeric_limits<T>::infinity(), hit)) {
      ++a.misses;
      continue;
    }
    const Real t = exactT(ray);
    const Vec3d n = toDouble(hit.normal);
    if (glm::dot(n, d) <= 0) ++a.wrongSide;
    a.worstDistance = std::max(
        a.worstDistance, double(std::abs(static_cast<Real>(static_cast<double>(hit.t)) - t)) * glm::length(d));
    a.worstNormalAngle = std::max(a.worstNormalAngle, angleBetween(n, exactNormal(ray, t)));
  }
  return a;
}

template <typename T>
void checkInside(const std::string& what, const InsideAgreement& a, double distanceBound, double angleBound) {
  INFO(what);
  reportMeasure(what + ": distance error (object sizes)", a.worstDistance, distanceBound);
  reportMeasure(what + ": normal angle (rad)", a.worstNormalAngle, angleBound);
  CHECK(a.misses == 0);
  CHECK(a.wrongSide == 0);  // never the surface behind the eye, never the far side's outer face
  CHECK(a.worstDistance <= distanceBound);
  CHECK(a.worstNormalAngle <= angleBound);
}

// World normal of an implicit local solid at the exact hit, via the inverse
// transpose of the placement and a central-difference gradient.
template <typename T, typename F>
Vec3d exactWorldNormal(F f, const Ray<T>& ray, Real t, const Mat4d& place) {
  const RealVec p = exactRay(ray, glm::inverse(place)).at(t);
  const Real h = 1e-7L;
  const Vec3d g(double((f(RealVec{p.x + h, p.y, p.z}) - f(RealVec{p.x - h, p.y, p.z})) / (2 * h)),
                double((f(RealVec{p.x, p.y + h, p.z}) - f(RealVec{p.x, p.y - h, p.z})) / (2 * h)),
                double((f(RealVec{p.x, p.y, p.z + h}) - f(RealVec{p.x, p.y, p.z - h})) / (2 * h)));
  return glm::normalize(glm::transpose(glm::inverse(glm::dmat3(place))) * g);
}

}  // namespace

TEMPLATE_TEST_CASE("extremes: a camera inside a sphere a torus and CSG solids sees the inside surface", "[extremes]",
                   float, double, Fixed32) {
  using T = TestType;
  // Bounds on the distance error (object sizes) and the normal's angle;
  // the measured figures are in docs/stability.md.
  const double tBound = bound<T>(1e-5, 1e-12, 1e-7);
  const double angleBound = bound<T>(1e-4, 1e-9, 1e-6);
  const Mat4d toLocal = glm::inverse(kPlace);
  const auto sphereF = [](const RealVec& p) { return sphereFunction(p, 1); };
  const auto torusF = [](const RealVec& p) { return torusFunction(p, kMajor, kMinor); };
  const QuarticShape sphereShape = sphere(1.0), torusShape = torus(kMajor, kMinor);
  const auto name = [&](const char* what) { return fmt::format("{} camera inside {}", arithmeticName<T>(), what); };

  SECTION("a sphere, from its centre and from 1e-3 under its surface") {
    const auto leaf = makeQuarticLeaf<T>(sphereShape.f, sphereShape.bounds, kPlace, 0);
    for (double depth : {1.0, 1e-3}) {
      // 1e-3 under the surface point (0, 0, -1): half the rays leave within
      // about 1e-3, the rest cross the whole sphere.
      const Vec3d eye = transformPoint(kPlace, Vec3d(0, 0, -1 + depth));
      const auto exactT = [&](const Ray<T>& ray) { return exactExit(sphereF, exactRay(ray, toLocal), Real(1e-4)); };
      const auto normal = [&](const Ray<T>& ray, Real t) { return exactWorldNormal(sphereF, ray, t, kPlace); };
      checkInside<T>(name(depth == 1.0 ? "sphere, at its centre" : "sphere, 1e-3 under its surface"),
                     fromInside(*leaf, eye, exactT, normal), tBound, angleBound);
    }
  }
  SECTION("a torus, from a point of its tube's centre line") {
    const auto leaf = makeQuarticLeaf<T>(torusShape.f, torusShape.bounds, kPlace, 0);
    const Vec3d eye = transformPoint(kPlace, Vec3d(kMajor, 0, 0));
    const auto exactT = [&](const Ray<T>& ray) { return exactExit(torusF, exactRay(ray, toLocal), Real(1e-4)); };
    const auto normal = [&](const Ray<T>& ray, Real t) { return exactWorldNormal(torusF, ray, t, kPlace); };
    checkInside<T>(name("torus"), fromInside(*leaf, eye, exactT, normal), tBound, angleBound);
  }
  SECTION("CSG: a union and an intersection of overlapping spheres, a sphere with a hole") {
    // Spheres A at x = -0.5 and B at x = +0.5 (radius 1), the eye at the
    // origin, inside both. Inner surfaces (A's boundary inside B) are not
    // surfaces of the union and must not be reported.
    const Mat4d a = kPlace * glm::translate(Mat4d(1.0), Vec3d(-0.5, 0, 0));
    const Mat4d b = kPlace * glm::translate(Mat4d(1.0), Vec3d(0.5, 0, 0));
    const Mat4d hole = kPlace * glm::translate(Mat4d(1.0), Vec3d(0.3, 0.2, 0)) * glm::scale(Mat4d(1.0), Vec3d(0.25));
    const auto inA = [](const RealVec& p) { return sphereFunction(RealVec{p.x + 0.5L, p.y, p.z}, 1); };
    const auto inB = [](const RealVec& p) { return sphereFunction(RealVec{p.x - 0.5L, p.y, p.z}, 1); };
    const auto inHole = [](const RealVec& p) { return sphereFunction(RealVec{p.x - 0.3L, p.y - 0.2L, p.z}, 0.25L); };
    const auto both = [&](CsgOp op, const Mat4d& second) {
      std::vector<PrimitivePtr<T>> parts;
      parts.push_back(makeQuarticLeaf<T>(sphereShape.f, sphereShape.bounds, a, 0));
      parts.push_back(makeQuarticLeaf<T>(sphereShape.f, sphereShape.bounds, second, 0));
      return makeCsgNode<T>(op, std::move(parts));
    };
    const Vec3d eye = transformPoint(kPlace, Vec3d(0, 0, 0));
    struct Op {
      const char* what;
      CsgOp op;
      const Mat4d& second;
      std::function<Real(const RealVec&)> f;  // < 0 inside the result
    };
    const Op ops[] = {
        {"union", CsgOp::Union, b, [&](const RealVec& p) { return std::min(inA(p), inB(p)); }},
        {"intersection", CsgOp::Intersection, b, [&](const RealVec& p) { return std::max(inA(p), inB(p)); }},
        // The eye is inside A and outside the hole: rays towards the hole
        // leave the solid at the hole's surface.
        {"difference", CsgOp::Difference, hole, [&](const RealVec& p) { return std::max(inA(p), -inHole(p)); }},
    };
    for (const Op& op : ops) {
      const auto solid = both(op.op, op.second);
      const auto exactT = [&](const Ray<T>& ray) { return exactExit(op.f, exactRay(ray, toLocal), Real(1e-4)); };
      // Which sphere the exact exit lies on decides the normal.
      const auto normal = [&](const Ray<T>& ray, Real t) {
        const RealVec p = exactRay(ray, toLocal).at(t);
        const Real da = std::abs(inA(p)), db = std::abs(op.op == CsgOp::Difference ? inHole(p) : inB(p));
        if (da <= db) return exactWorldNormal(inA, ray, t, kPlace);
        return op.op == CsgOp::Difference ? -exactWorldNormal(inHole, ray, t, kPlace)
                                          : exactWorldNormal(inB, ray, t, kPlace);
      };
      checkInside<T>(name(op.what), fromInside(*solid, eye, exactT, normal), tBound, angleBound);
    }
  }
  SECTION("a render from inside a lit sphere matches double") {
    const std::string text =
        "[options]\nwidth = 32\nheight = 32\nK = 0\nbackground = [1.0, 0.0, 0.0]\n"
        "[camera]\ntype = \"look_at\"\neye = [0.1, -0.2, 0.05]\ntarget = [0.3, 0.0, 1.0]\nfov = 90\n"
        "[[lights]]\nposition = [-0.3, 0.4, -0.2]\nintensity = 0.5\n"
        "[[objects]]\ntype = \"sphere\"\nradius = 1.0\n";
    const SceneDesc scene = parseScene(text, "inside.toml");
    Renderer<T> renderer(scene, settings(32));
    Renderer<double> reference(scene, settings(32));
    const RgbImage image = renderImage(renderer);
    // Every ray meets the inner surface: no pixel is the (red) background.
    int background = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        if (image.pixel(x, y)[0] == 255 && image.pixel(x, y)[1] == 0) ++background;
    CHECK(background == 0);
    const FixedVsDouble m = compareRenders(image, renderImage(reference));
    reportMeasure(name("a lit sphere") + ": image PSNR (dB) vs double", m.psnr, 45.0);
    CHECK(m.psnr > 45.0);
  }
}

// ---------------------------------------------------------------- nearly singular transforms

TEST_CASE("extremes: the condition number of a transform") {
  // diag(1, 1, e): 1 / e, whatever rotation and translation follow.
  for (double e : {1.0, 1e-3, 1e-6, 1e-9}) {
    const Mat4d squash = glm::scale(Mat4d(1.0), Vec3d(1, 1, e));
    CHECK(conditionNumber(squash) == Approx(1 / e).epsilon(1e-9));
    CHECK(conditionNumber(kPlace * squash * glm::rotate(Mat4d(1.0), 0.3, Vec3d(0, 1, 0))) ==
          Approx(1 / e).epsilon(1e-6));
  }
  // Two unit columns at an angle theta: cot(theta / 2).
  for (double theta : {1.0, 1e-3, 2e-6}) {
    Mat4d m(1.0);
    m[1] = glm::dvec4(std::cos(theta), std::sin(theta), 0, 0);
    CHECK(conditionNumber(m) == Approx(1 / std::tan(theta / 2)).epsilon(1e-6));
  }
  CHECK(std::isinf(conditionNumber(glm::scale(Mat4d(1.0), Vec3d(1, 0, 1)))));
  Mat4d nan(1.0);
  nan[0][0] = std::nan("");
  CHECK(std::isinf(conditionNumber(nan)));
  CHECK(conditionNumber(glm::scale(Mat4d(1.0), Vec3d(1e-4))) == Approx(1.0));  // uniform: perfectly conditioned
}

namespace {

// Loads `text`, expecting an Input error at `line` whose message contains
// every one of `expected`.
void requireLoadError(const std::string& text, int line, std::initializer_list<std::string> expected) {
  TempScene scene(text);
  try {
    scene.load();
    FAIL("expected an error for:\n" << text);
  } catch (const Error& e) {
    INFO("message: " << e.what());
    REQUIRE(e.kind() == ErrorKind::Input);
    REQUIRE_THAT(std::string(e.what()), Catch::StartsWith(fmt::format("{}:{}:", scene.path().string(), line)));
    for (const auto& piece : expected) REQUIRE_THAT(std::string(e.what()), Catch::Contains(piece));
  }
}

std::string sphereWith(const std::string& transformKeys) {
  return "[[objects]]\ntype = \"sphere\"\nradius = 1\n" + transformKeys + "\n";
}

// Columns (1, 0, 0), (cos theta, sin theta, 0), (0, 0, 1): two axes theta
// apart, condition number cot(theta / 2).
std::string shearMatrix(double theta) {
  return fmt::format("matrix = [[1, {:.17g}, 0, 0], [0, {:.17g}, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
                     std::cos(theta), std::sin(theta));
}

}  // namespace

TEST_CASE("extremes: nearly singular transforms are refused at scene load") {
  // The limit: condition number 1e6 (render/transform_condition.hpp). Each
  // side of it, as a squashing scale and as two nearly parallel axes.
  SECTION("a scale flattening the sphere to nothing") {
    requireLoadError(sphereWith("scale = [1, 1, 1e-13]"), 4, {"singular", "condition number", "1e6"});
    requireLoadError(sphereWith("scale = [1, 1, 0]"), 4, {"singular", "non-zero"});
  }
  SECTION("scale factors 1e6 apart, just either side") {
    requireLoadError(sphereWith("scale = [1, 1, 0.99e-6]"), 4, {"nearly singular", "1.01e+06", "within a factor 1e6"});
    CHECK_NOTHROW(TempScene(sphereWith("scale = [1, 1, 1.01e-6]")).load());
    CHECK_NOTHROW(TempScene(sphereWith("scale = [1e4, 1e4, 1.01e-2]")).load());
  }
  SECTION("two nearly parallel axes, just either side") {
    // cot(theta / 2) = 1e6 at theta = 2e-6.
    requireLoadError(sphereWith(shearMatrix(1.98e-6)), 4, {"nearly singular", "columns far from parallel"});
    CHECK_NOTHROW(TempScene(sphereWith(shearMatrix(2.02e-6))).load());
  }
  SECTION("scale factors outside 1e-9..1e9") {
    requireLoadError(sphereWith("scale = 1e-10"), 4, {"outside 1e-9..1e9", "radius"});
    CHECK_NOTHROW(TempScene(sphereWith("scale = 1e-4")).load());
    CHECK_NOTHROW(TempScene(sphereWith("scale = 1e4")).load());
  }
  SECTION("squashes that multiply down the tree, named at the leaf") {
    // 1e-3 on the union times 1e-4 on its child: 1e7 at the child (line 4).
    requireLoadError("[[objects]]\ntype = \"union\"\nscale = [1, 1, 1e-3]\n"
                     "children = [ { type = \"sphere\", radius = 1, scale = [1, 1, 1e-4] } ]\n",
                     4, {"with the transforms of the objects around it", "nearly singular"});
    CHECK_NOTHROW(TempScene("[[objects]]\ntype = \"union\"\nscale = [1, 1, 1e-3]\n"
                            "children = [ { type = \"sphere\", radius = 1, scale = [1, 1, 1e-2] } ]\n")
                      .load());
  }
}

TEMPLATE_TEST_CASE("extremes: transforms just inside each arithmetic's condition limit render exactly enough",
                   "[extremes]", float, double, Fixed32) {
  using T = TestType;
  // A unit sphere flattened to a disc 1/kappa thick, tilted: the ray's
  // entry against the exact ellipsoid (long double) for every primary ray.
  // Just above the limit: float refuses when the scene is built (1e4), the
  // scene file is refused for everyone at 1e6.
  const double limit = maxTransformCondition<T>();
  const auto scene = [](double kappa) {
    return parseScene(fmt::format("[camera]\ntype = \"look_at\"\neye = [0.3, 2.0, -4.0]\ntarget = [0.0, 0.0, 0.0]\n"
                                  "fov = 40\n[[objects]]\ntype = \"sphere\"\nradius = 1\n"
                                  "scale = [1, 1, {:.17g}]\nrotate = {{ axis = [1.0, 1.0, 0.0], degrees = 23 }}\n",
                                  1 / kappa),
                      "thin.toml");
  };
  const SceneDesc near = scene(0.99 * limit);
  Renderer<T> renderer(near, settings(40));
  // The same placement, in double, for the exact reference.
  const Mat4d place = glm::rotate(Mat4d(1.0), 23 * 3.14159265358979323846 / 180, glm::normalize(Vec3d(1, 1, 0))) *
                      glm::scale(Mat4d(1.0), Vec3d(1, 1, 1 / (0.99 * limit)));
  const Mat4d toLocal = glm::inverse(place);
  int disagreements = 0, hits = 0;
  double worstT = 0, worstAngle = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const Ray<T> ray = renderer.camera().primaryRay(x, y);
      const ExactRay local = exactRay(ray, toLocal);
      const RealVec& o = local.origin;
      const RealVec& d = local.direction;
      const Real a = d.x * d.x + d.y * d.y + d.z * d.z, b = o.x * d.x + o.y * d.y + o.z * d.z;
      const Real c = o.x * o.x + o.y * o.y + o.z * o.z - 1;
      const Real disc = b * b - a * c;
      // The local distance between the line and the centre, minus 1: rays
      // within float's reach of the rim may go either way.
      const Real clearance = std::sqrt(std::max(Real(0), c + 1 - b * b / a)) - 1;
      Hit<T> hit;
      const bool got = renderer.root().firstHit(ray, T(0), std::numeric_limits<T>::infinity(), hit);
      if (got != (disc > 0)) {
        if (std::abs(clearance) > 1e-6) ++disagreements;
        continue;
      }
      if (!got) continue;
      ++hits;
      const Real t = (-b - std::sqrt(disc)) / a;
      worstT = std::max(worstT, double(std::abs(static_cast<Real>(static_cast<double>(hit.t)) - t) / t));
      const RealVec p = local.at(t);
      const Vec3d n = glm::transpose(glm::dmat3(toLocal)) * Vec3d(double(p.x), double(p.y), double(p.z));
      worstAngle = std::max(worstAngle, angleBetween(toDouble(hit.normal), glm::normalize(n)));
    }
  const std::string what = fmt::format("{} condition number {:g}", arithmeticName<T>(), 0.99 * limit);
  // Measured: float 1.5e-7 relative in t, 1.5e-6 rad; double 4e-12, 2e-8;
  // Q31.32 3.3e-9, 2.5e-5.
  const double tBound = bound<T>(1e-5, 1e-10, 1e-7);
  const double angleBound = bound<T>(1e-4, 1e-6, 1e-4);
  reportMeasure(what + ": relative t error", worstT, tBound);
  reportMeasure(what + ": normal angle (rad)", worstAngle, angleBound);
  REQUIRE(hits > 300);
  CHECK(disagreements == 0);
  CHECK(worstT <= tBound);
  CHECK(worstAngle <= angleBound);

  if constexpr (std::is_same_v<T, float>) {
    // Loads (below the file limit 1e6); refused when built, naming the object.
    const SceneDesc beyond = scene(1.01 * limit);
    REQUIRE_THROWS_WITH(Renderer<T>(beyond, settings(8)), Catch::Contains("thin.toml:6:") &&
                                                              Catch::Contains("--arith float") &&
                                                              Catch::Contains("use --arith double"));
    REQUIRE_NOTHROW(Renderer<double>(beyond, settings(8)));
  } else {
    // Named at the object's transform keys (scale and rotate; line 10 is rotate).
    REQUIRE_THROWS_WITH(scene(1.01 * limit), Catch::Contains("thin.toml:10:") && Catch::Contains("nearly singular"));
  }
}
