// --arith fixed: the whole per-pixel path in Q31.32 (render/fixed.hpp).
// Renders of the example scenes against double, the fixed-point root solver
// on the hard cases of tests/render/roots_test.cpp, scenes at the edges of
// the Q31.32 range, and a scan of the compiled Fixed32 code for
// floating-point instructions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "render/shapes/quartic.hpp"
#include "render/solve/roots.hpp"
#include "render/shapes/quartic_presets.hpp"
#include "loader/scene_loader.hpp"
#include "tests/render/fixed_support.hpp"
#include "tests/render/scene_test_util.hpp"
#include "tests/support/golden.hpp"

using namespace lattice;

namespace {

RenderSettings sized(int w, int h) {
  RenderSettings s;
  s.width = w;
  s.height = h;
  s.threads = 2;
  return s;
}

testing::FixedVsDouble fixedVsDouble(const SceneDesc& scene, int w, int h) {
  Renderer<Fixed32> f(scene, sized(w, h));
  Renderer<double> d(scene, sized(w, h));
  return testing::compareRenders(renderImage(f), renderImage(d));
}

// Coefficients (lowest power first) of lead * prod (x - r_i), expanded in
// long double, converted to Q31.32 once.
std::vector<Fixed32> fromRoots(const std::vector<long double>& roots, long double lead = 1) {
  std::vector<long double> c{lead};
  for (long double r : roots) {
    std::vector<long double> next(c.size() + 1, 0);
    for (std::size_t k = 0; k < c.size(); ++k) {
      next[k + 1] += c[k];
      next[k] -= r * c[k];
    }
    c = next;
  }
  std::vector<Fixed32> out;
  for (long double v : c) out.push_back(Fixed32(static_cast<double>(v)));
  return out;
}

std::vector<double> solveFixed(const std::vector<Fixed32>& c) {
  Fixed32 roots[4];
  const int n = solvePolynomial<Fixed32>(std::span<const Fixed32>(c), roots);
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(roots[i].toDouble());
  for (std::size_t i = 1; i < out.size(); ++i) REQUIRE(out[i - 1] < out[i]);  // ascending, distinct
  return out;
}

// Every expected root has a returned root within `tolerance` (absolute),
// and every returned root is near an expected one.
void checkNear(const std::vector<double>& got, const std::vector<double>& expected, double tolerance) {
  INFO("got " << got.size() << " roots");
  for (double e : expected) {
    double best = INFINITY;
    for (double g : got) best = std::min(best, std::abs(g - e));
    INFO("expected root " << e << ", nearest error " << best);
    CHECK(best <= tolerance);
  }
  for (double g : got) {
    double best = INFINITY;
    for (double e : expected) best = std::min(best, std::abs(g - e));
    INFO("returned root " << g << " is " << best << " from any expected root");
    CHECK(best <= tolerance);
  }
}

}  // namespace

TEST_CASE("fixed point: the three example scenes match the double render") {
  // Measured at 96x96 (docs/fixed-point.md): sphere-hole and thesis-camera
  // identical, torus-floor 92.5 dB (no channel off by more than 1); stated
  // bound 35 dB and <1% of channels off by more than 4 levels.
  for (const char* name : {"sphere-hole", "torus-floor", "thesis-camera"}) {
    INFO(name);
    const SceneDesc scene = loadScene(testing::sourcePath(std::string("scenes/") + name + ".toml"));
    const testing::FixedVsDouble m = fixedVsDouble(scene, 96, 96);
    INFO("PSNR " << m.psnr << " dB, channels off by > 4: " << 100 * m.farFraction << "%, max " << m.maxDelta);
    CHECK(m.psnr > 35.0);
    CHECK(m.farFraction < 0.01);
  }
}

TEST_CASE("fixed point: Q31.32 output is not the double output in disguise") {
  // The fixed renderer must really compute in fixed point: its linear
  // pixel values carry Q31.32 rounding, so somewhere they differ from double
  // in the low bits while agreeing to ~1e-6.
  const SceneDesc scene = loadScene(testing::sourcePath("scenes/torus-floor.toml"));
  Renderer<Fixed32> f(scene, sized(24, 24));
  Renderer<double> d(scene, sized(24, 24));
  int differing = 0, close = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      const Vec3<Fixed32> a = f.pixel(x, y);
      const Vec3d b = d.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        const double delta = std::abs(a[c].toDouble() - b[c]);
        if (delta != 0.0) ++differing;
        if (delta < 1e-5) ++close;
      }
    }
  CHECK(differing > 0);
  CHECK(close > 24 * 24 * 3 * 95 / 100);
}

TEST_CASE("fixed point: roots of the standard hard cases") {
  // Q31.32 coefficients carry an absolute error of 2^-33; a simple root r
  // then moves by about 2^-33 * sum|c_k r^k| / |p'(r)|, a root of
  // multiplicity m by about (that)^(1/m). The bounds below are those
  // estimates with a margin of 4 to 10 (measured errors in comments).
  SECTION("simple roots of mixed sign") {
    checkNear(solveFixed(fromRoots({-3, -1, 2, 7})), {-3, -1, 2, 7}, 1e-8);
    checkNear(solveFixed(fromRoots({-0.5, 0.25, 1})), {-0.5, 0.25, 1}, 1e-8);
  }
  SECTION("spread over seven orders of magnitude") {
    // 1e3, 1, 1e-3: the large root is the condition-limited one.
    checkNear(solveFixed(fromRoots({1e3L, 1, 1e-3L})), {1e3, 1, 1e-3}, 1e-6);
    // 1e4 .. 1e-2 (coefficients up to 1e4).
    checkNear(solveFixed(fromRoots({1e4L, 1e2L, 1, 1e-2L})), {1e4, 1e2, 1, 1e-2}, 1e-4);
  }
  SECTION("degree 1 (a plane's ray): one root, on either side of |x| = 1 and at it") {
    // The solver runs only the side of |y| = 1 that can hold -c0/c1, both
    // when the scaled coefficients are equal in size: every case one root.
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
      const double c1 = unit(rng) * std::ldexp(1.0, static_cast<int>(rng() % 24) - 12);
      double c0 = unit(rng) * std::ldexp(1.0, static_cast<int>(rng() % 24) - 12);
      if (i % 4 == 0) c0 = (i % 8 == 0 ? 1 : -1) * std::ldexp(c1, static_cast<int>(rng() % 5) - 2);  // |x| a power of 2
      const std::vector<Fixed32> line{Fixed32(c0), Fixed32(c1)};
      if (line[0].raw() == 0 || line[1].raw() == 0) continue;
      const double x = -line[0].toDouble() / line[1].toDouble();
      if (std::abs(x) >= std::ldexp(1.0, 30)) continue;  // beyond Q31.32's reach: saturated, not this test's
      const auto r = solveFixed(line);
      INFO("c0 = " << c0 << ", c1 = " << c1);
      REQUIRE(r.size() == 1);
      CHECK(std::abs(r[0] - x) <= 1e-9 * std::max(1.0, std::abs(x)));
    }
  }
  SECTION("no cancellation in the quadratic") {
    // x^2 - 1e4 x + 1: roots 1.00000001e-4 and 9999.9999 (exact below).
    const std::vector<Fixed32> q{Fixed32(1), Fixed32(-1e4), Fixed32(1)};
    const auto r = solveFixed(q);
    REQUIRE(r.size() == 2);
    const long double small = 2.0L / (1e4L + std::sqrt(1e8L - 4.0L));
    CHECK(std::abs(r[0] - static_cast<double>(small)) <= 1e-9);
    CHECK(std::abs(r[1] - static_cast<double>(1.0L / small)) <= 1e-6);
  }
  SECTION("clusters") {
    // 2, 2.1, 2.2, 2.3 is resolved; |p'| ~ 2e-3 at the inner roots, so the
    // estimate is 2^-33 * ~100 / 2e-3 ~ 6e-6 (measured 4.8e-7).
    const auto r = solveFixed(fromRoots({2, 2.1L, 2.2L, 2.3L}));
    REQUIRE(r.size() == 4);
    checkNear(r, {2, 2.1, 2.2, 2.3}, 6e-6);
    // 2, 2.001, 2.002, 2.003 is not: between its roots |p| < 6e-13, far below
    // the 2^-33 rounding of the coefficients (times sum |c_k x^k| ~ 100), so
    // the Q31.32 polynomial has fewer real roots: it behaves like a quadruple
    // root, within (1e-8)^(1/4) ~ 1e-2 (measured 5.6e-3 from the centre).
    const auto c = solveFixed(fromRoots({2, 2.001L, 2.002L, 2.003L}));
    CHECK(c.size() <= 4);
    for (double x : c) CHECK(std::abs(x - 2.0015) <= 2e-2);
  }
  SECTION("multiple roots come back within (2^-32)^(1/m)") {
    // Double roots: within ~sqrt(2^-32 * |c|) ~ 1e-4; they may split into two
    // or merge into one, as the contract allows.
    checkNear(solveFixed(fromRoots({1, 1, 3, 3})), {1, 3}, 1e-3);
    checkNear(solveFixed(fromRoots({2, 2, -1, 5})), {2, -1, 5}, 1e-3);
    // A quadruple root: (2^-33 / 1)^(1/4) ~ 7e-3.
    checkNear(solveFixed(fromRoots({1.5, 1.5, 1.5, 1.5})), {1.5}, 3e-2);
  }
  SECTION("complex pairs give only the real roots") {
    // (x^2 + 1)(x - 2)(x + 0.5)
    std::vector<Fixed32> c = {Fixed32(-1.0), Fixed32(-1.5), Fixed32(0.0), Fixed32(-1.5), Fixed32(1.0)};
    checkNear(solveFixed(c), {-0.5, 2}, 1e-8);
    // x^4 + 1: none.
    CHECK(solveFixed({Fixed32(1), Fixed32(0), Fixed32(0), Fixed32(0), Fixed32(1)}).empty());
  }
  SECTION("degenerate inputs") {
    CHECK(solveFixed({Fixed32(0), Fixed32(0), Fixed32(0)}).empty());  // zero polynomial
    CHECK(solveFixed({Fixed32(3), Fixed32(0)}).empty());                // non-zero constant
    checkNear(solveFixed({Fixed32(0), Fixed32(0), Fixed32(2)}), {0}, 0);  // 2 x^2
    checkNear(solveFixed({Fixed32(0), Fixed32(-4), Fixed32(0), Fixed32(1)}), {-2, 0, 2}, 1e-9);
    // Leading zeros lower the degree.
    checkNear(solveFixed({Fixed32(-6), Fixed32(3), Fixed32(0), Fixed32(0), Fixed32(0)}), {2}, 1e-9);
  }
  SECTION("roots beyond the Q31.32 range come back saturated, never wrapped") {
    // 1e-6 x^2 - 1e4 x + 1: roots 1e-4 and 1e10 (> 2^31).
    const auto r = solveFixed({Fixed32(1), Fixed32(-1e4), Fixed32(1e-6)});
    REQUIRE(r.size() == 2);
    CHECK(std::abs(r[0] - 1e-4) <= 1e-8);
    CHECK(r[1] == std::numeric_limits<Fixed32>::max().toDouble());
  }
}

TEST_CASE("fixed point: roots agree with double on random torus rays") {
  // Rays re-based near the torus, as the quartic leaf does: coefficients of
  // order 1..10. Roots of both solvers agree to 1e-5 wherever double finds
  // well-separated roots (gap > 1e-2), and the root counts match there.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int compared = 0;
  for (int i = 0; i < 400; ++i) {
    const double o[3] = {2 * u(rng), 2 * u(rng), 1.5 * u(rng)};
    double d[3] = {u(rng), u(rng), u(rng)};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& v : d) v /= len;
    const double R = 1.0, r = 0.3;
    const double dd = 1.0, od = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
    const double oo = o[0] * o[0] + o[1] * o[1] + o[2] * o[2], k = oo + R * R - r * r;
    const double dxy = d[0] * d[0] + d[1] * d[1], oxy = o[0] * d[0] + o[1] * d[1], ooxy = o[0] * o[0] + o[1] * o[1];
    const double r4 = 4 * R * R;
    const std::array<double, 5> c = {k * k - r4 * ooxy, 4 * od * k - r4 * 2 * oxy, 4 * od * od + 2 * dd * k - r4 * dxy,
                                     4 * dd * od, dd * dd};
    // The same (rounded) coefficients for both solvers.
    std::array<Fixed32, 5> cf{};
    std::array<double, 5> cd{};
    for (int n = 0; n < 5; ++n) {
      cf[n] = Fixed32(c[n]);
      cd[n] = cf[n].toDouble();
    }
    double rd[4];
    Fixed32 rf[4];
    const int nd = solvePolynomial<double>(std::span<const double>(cd), rd);
    const int nf = solvePolynomial<Fixed32>(std::span<const Fixed32>(cf), rf);
    bool separated = true;
    for (int n = 1; n < nd; ++n) separated = separated && rd[n] - rd[n - 1] > 1e-2;
    if (!separated) continue;
    ++compared;
    INFO("ray " << i);
    REQUIRE(nf == nd);
    for (int n = 0; n < nd; ++n) CHECK(std::abs(rf[n].toDouble() - rd[n]) <= 1e-5);
  }
  CHECK(compared > 300);
}

TEST_CASE("fixed point: scenes at the edges of the Q31.32 range never crash") {
  // What happens (docs/fixed-point.md, "Where fixed point cannot follow"):
  // objects of size 1e4 or 1e-3, or 1e4 units away, render like double
  // (quartic leaves normalize their polynomial to coefficients of order 1);
  // coordinates beyond +-2^31 saturate and give another picture, never a
  // crash.
  auto scene = [](const std::string& object, const std::string& eye, const std::string& light) {
    return testing::TempScene(
        "[options]\nwidth = 32\nheight = 32\nK = 0\nbackground = [0.1, 0.2, 0.3]\n"
        "[camera]\ntype = \"look_at\"\neye = " + eye + "\ntarget = [0.0, 0.0, 0.0]\nfov = 30\n"
        "[[lights]]\nposition = " + light + "\nintensity = 1.0\n"
        "[[objects]]\n" + object);
  };
  SECTION("a unit sphere seen from 1e4 units") {
    const testing::TempScene s = scene("type = \"sphere\"\nradius = 1.0\ntranslate = [1e4, 0.0, 0.0]\n",
                                       "[9990.0, 0.0, -10.0]", "[1e4, 50.0, -50.0]");
    // The camera looks at the origin; aim it at the sphere instead.
    SceneDesc desc = s.load();
    desc.camera.target = Vec3d(1e4, 0.0, 0.0);
    const testing::FixedVsDouble m = fixedVsDouble(desc, 32, 32);
    INFO("PSNR " << m.psnr << ", far " << m.farFraction);
    CHECK(m.psnr > 35.0);
  }
  SECTION("a sphere of radius 1e4") {
    const testing::TempScene s = scene("type = \"sphere\"\nradius = 1e4\n", "[0.0, 0.0, -4e4]", "[0.0, 3e4, -3e4]");
    const testing::FixedVsDouble m = fixedVsDouble(s.load(), 32, 32);
    INFO("PSNR " << m.psnr << ", far " << m.farFraction);
    CHECK(m.psnr > 35.0);
  }
  SECTION("a torus of size 1e4") {
    // Without the leaf's power-of-two normalization its x^4 coefficient would
    // be 1e-8 = 43 units of 2^-32 (measured before it: 23 dB); with it, equal.
    const testing::TempScene s = scene("type = \"torus\"\nmajor = 1e4\nminor = 3e3\n", "[0.0, 3e4, -3e4]",
                                       "[0.0, 5e4, -5e4]");
    const testing::FixedVsDouble m = fixedVsDouble(s.load(), 32, 32);
    INFO("PSNR " << m.psnr << ", far " << m.farFraction);
    CHECK(m.psnr > 35.0);
  }
  SECTION("a shape whose transform needs more than 2^31 is refused when the scene is built") {
    // A sphere of radius 4e9: its normalized object space has the scale
    // 2^32, which Q31.32 cannot hold. A clear error, before any pixel.
    const testing::TempScene s = scene("type = \"sphere\"\nradius = 4e9\n", "[0.0, 0.0, -1.2e10]",
                                       "[0.0, 1e10, -1e10]");
    const SceneDesc desc = s.load();
    REQUIRE_THROWS_WITH(Renderer<Fixed32>(desc, sized(8, 8)), Catch::Contains("--arith double"));
    REQUIRE_NOTHROW(Renderer<double>(desc, sized(8, 8)));
  }
  SECTION("a unit sphere 1e9 units away renders (sub-pixel) like double") {
    const testing::TempScene s = scene("type = \"sphere\"\nradius = 1.0\n", "[0.0, 0.0, -1e9]", "[0.0, 1e9, -1e9]");
    const testing::FixedVsDouble m = fixedVsDouble(s.load(), 32, 32);
    CHECK(m.psnr > 35.0);
  }
  SECTION("a sphere of radius 1e-3") {
    const testing::TempScene s = scene("type = \"sphere\"\nradius = 1e-3\n", "[0.0, 0.0, -4e-3]", "[0.0, 3e-3, -3e-3]");
    const testing::FixedVsDouble m = fixedVsDouble(s.load(), 32, 32);
    INFO("PSNR " << m.psnr << ", far " << m.farFraction << ", max " << m.maxDelta);
    CHECK(m.psnr > 30.0);
  }
}

TEST_CASE("fixed point: no floating-point instruction on the Fixed32 per-pixel path") {
#ifndef NDEBUG
  WARN("skipped: the scan needs an optimized build, where Fixed(double) of literals is folded at compile time");
#elif defined(LATTICE_SANITIZED)
  WARN("skipped under the sanitizers: UBSan's float-cast and ASan's checks add code of their own to every function, "
       "so the scan would read instrumentation, not our arithmetic (the g++ build runs it)");
#else
  // Disassembles the render library and lists every function instantiated
  // for Fixed32 (or in the fixed-point root solver) that contains an SSE/x87
  // floating-point instruction or calls a libm function. Only scene set-up
  // (constructors and builders, which convert the double scene once) may.
  const testing::FixedPointScan scan = testing::scanFixedPointCode(std::string(LATTICE_BINARY_DIR) +
                                                                   "/render/liblattice_render.a");
  const std::set<std::string>& fixedFunctions = scan.fixedFunctions;
  const std::set<std::string>& withFloatingPoint = scan.withFloatingPoint;
  // The scan saw the per-pixel code (else it could not fail).
  auto seen = [&](const char* part) {
    for (const std::string& f : fixedFunctions)
      if (f.find(part) != std::string::npos) return true;
    return false;
  };
  REQUIRE(seen("fixed_roots::solve"));
  REQUIRE(seen("QuarticLeaf<lattice::Fixed<32> >::spans"));
  REQUIRE(seen("Renderer<lattice::Fixed<32> >::trace"));
  // The union's queries are render/shapes/union_core.hpp's, instantiated for UnionNode.
  REQUIRE(seen("UnionCore<lattice::Fixed<32>, lattice::(anonymous namespace)::UnionNode<lattice::Fixed<32> >"));
  REQUIRE(std::any_of(fixedFunctions.begin(), fixedFunctions.end(), [](const std::string& f) {
    return f.find("UnionCore<lattice::Fixed<32>") != std::string::npos && f.find("::firstHit(") != std::string::npos;
  }));
  // The detector works: the set-up code (double -> Q31.32 conversions) shows up.
  REQUIRE_FALSE(withFloatingPoint.empty());
  for (const std::string& f : withFloatingPoint) {
    INFO("floating point in " << f);
    CHECK(testing::isSetUpCode(scan, f));
  }
#endif
}

TEST_CASE("fixed point: a hit beyond 2^31 saturates and is a miss") {
  // The floor y < 0 seen at a grazing angle from y = 1: double hits it at
  // t = 3e9; in Q31.32 that t saturates, i.e. lies at "infinity", so the ray
  // misses, as a ray parallel to the floor would.
  const QuarticShape floor = halfSpace(Vec3d(0, 1, 0), 0.0);
  const auto fixedLeaf = makeQuarticLeaf<Fixed32>(floor.f, floor.bounds, Mat4d(1.0), 0);
  const auto doubleLeaf = makeQuarticLeaf<double>(floor.f, floor.bounds, Mat4d(1.0), 0);
  const double dy = -1.0 / 3e9;
  Hit<double> hd;
  REQUIRE(doubleLeaf->firstHit(Ray<double>{Vec3d(0, 1, 0), Vec3d(1, dy, 0)}, 0.0, INFINITY, hd));
  CHECK(hd.t == Approx(3e9).epsilon(1e-9));
  Hit<Fixed32> hf;
  const Ray<Fixed32> ray{Vec3<Fixed32>(Fixed32(0), Fixed32(1), Fixed32(0)), Vec3<Fixed32>(Fixed32(1), Fixed32(dy), Fixed32(0))};
  CHECK_FALSE(fixedLeaf->firstHit(ray, Fixed32(0), std::numeric_limits<Fixed32>::infinity(), hf));
  // A hit at 1e9 is still in range and found.
  const Ray<Fixed32> nearer{Vec3<Fixed32>(Fixed32(0), Fixed32(1), Fixed32(0)),
                            Vec3<Fixed32>(Fixed32(1), Fixed32(-1.0 / 1e9), Fixed32(0))};
  REQUIRE(fixedLeaf->firstHit(nearer, Fixed32(0), std::numeric_limits<Fixed32>::infinity(), hf));
  // dy = -1e-9 is 4.29 units of 2^-32, rounded to 4: the hit moves to 1.07e9.
  CHECK(hf.t.toDouble() == Approx(std::pow(2.0, 32) / 4).epsilon(1e-6));
}

TEST_CASE("fixed point: pow, log2, exp2, round and length in integers") {
  // The Phong term raises cosines in (0, 1] to exponents of 1..200; the
  // result must match libm to about 1e-8 absolute (a few units of 2^-32
  // times the exponent).
  for (double x : {1.0, 0.999, 0.9, 0.5, 0.25, 0.1, 0.01}) {
    for (double n : {1.0, 2.5, 10.0, 60.0, 200.0}) {
      const double got = pow(Fixed32(x), Fixed32(n)).toDouble();
      INFO("x " << x << " n " << n);
      CHECK(std::abs(got - std::pow(x, n)) <= 1e-8 * n + 1e-9);
    }
  }
  // Against libm on the Q31.32 value itself (1e-9 is only 4 units of 2^-32).
  for (double x : {1e-9, 0.3, 1.0, 7.5, 1e6, 2e9})
    CHECK(std::abs(log2(Fixed32(x)).toDouble() - std::log2(Fixed32(x).toDouble())) <= 1e-9);
  for (double y : {-30.0, -1.5, 0.0, 0.3, 10.0, 30.9})
    CHECK(std::abs(exp2(Fixed32(y)).toDouble() - std::exp2(y)) <= 1e-9 * std::max(1.0, std::exp2(y)));
  CHECK(exp2(Fixed32(40)) == std::numeric_limits<Fixed32>::max());  // saturates
  CHECK(exp2(Fixed32(-40)) == Fixed32(0));                          // below the resolution
  CHECK(round(Fixed32(2.5)).toDouble() == 3.0);
  CHECK(round(Fixed32(-2.5)).toDouble() == -3.0);
  CHECK(round(Fixed32(-2.49)).toDouble() == -2.0);
  // length() sums squares in 128 bits: no overflow where x^2 alone would saturate.
  const Vec3<Fixed32> big(Fixed32(3e8), Fixed32(4e8), Fixed32(0));
  CHECK(lattice::length(big).toDouble() == Approx(5e8).epsilon(1e-12));
  const Vec3<Fixed32> tiny(Fixed32::fromRaw(3), Fixed32::fromRaw(4), Fixed32(0));
  CHECK(lattice::length(tiny).raw() == 5);
}
