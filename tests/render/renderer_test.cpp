// The row renderer: 18-bit rounding, determinism across threads and repeated
// rows, and float vs double agreement on a real scene.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <vector>

#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "tests/support/golden.hpp"
#include "foundation/error.hpp"

using namespace lattice;

namespace {

SceneDesc exampleScene(const std::string& name) {
  return loadScene(lattice::testing::sourcePath("scenes/" + name));
}

RenderSettings sized(int w, int h, int threads) {
  RenderSettings s;
  s.width = w;
  s.height = h;
  s.threads = threads;
  return s;
}

template <typename T>
std::vector<Color18> allRows(Renderer<T>& r, bool reverse = false) {
  std::vector<Color18> out(static_cast<std::size_t>(r.width() * r.height()));
  for (int i = 0; i < r.height(); ++i) {
    const int y = reverse ? r.height() - 1 - i : i;
    r.row(y, std::span<Color18>(out).subspan(static_cast<std::size_t>(y * r.width()),
                                             static_cast<std::size_t>(r.width())));
  }
  return out;
}

}  // namespace

TEST_CASE("renderer: 6-bit channels round to nearest and clamp") {
  REQUIRE(quantize6(0.0) == 0);
  REQUIRE(quantize6(1.0) == 63);
  REQUIRE(quantize6(-0.5) == 0);
  REQUIRE(quantize6(7.0) == 63);
  REQUIRE(quantize6(0.49 / 63) == 0);
  REQUIRE(quantize6(0.51 / 63) == 1);
  REQUIRE(quantize6(31.6 / 63) == 32);
  REQUIRE(quantize8(0.5) == 128);
}

TEST_CASE("renderer: row matches the full-precision row quantized to 18 bits") {
  Renderer<double> r(exampleScene("torus-floor.toml"), sized(40, 30, 2));
  std::vector<Color18> row(40);
  std::vector<Vec3d> linear(40);
  for (int y : {0, 12, 29}) {
    r.row(y, row);
    r.rowLinear(y, linear);
    for (int x = 0; x < 40; ++x) {
      const Vec3d& c = linear[static_cast<std::size_t>(x)];
      REQUIRE(row[static_cast<std::size_t>(x)] == packColor18(quantize6(c.r), quantize6(c.g), quantize6(c.b)));
    }
  }
  // The scene is not blank: the torus, the floor and the sky differ.
  r.row(29, row);
  std::vector<Color18> top(40);
  r.row(0, top);
  REQUIRE(row[20] != top[20]);
}

TEST_CASE("renderer: multithreaded output equals single-threaded in any row order") {
  const SceneDesc scene = exampleScene("sphere-hole.toml");
  Renderer<double> one(scene, sized(48, 40, 1));
  Renderer<double> four(scene, sized(48, 40, 4));
  REQUIRE(four.threads() == 4);
  const auto a = allRows(one);
  const auto b = allRows(four, true);
  REQUIRE(a == b);
  // Asking again gives the same colours (two-pass quantizers rely on it).
  REQUIRE(allRows(four) == a);
  // The whole-image path agrees with itself across thread counts too.
  const RgbImage i1 = renderImage(one);
  const RgbImage i4 = renderImage(four);
  REQUIRE(i1.rgb == i4.rgb);
  REQUIRE(one.raysTraced() > 0);
}

TEST_CASE("renderer: float and double renders agree within a tolerance") {
  for (const char* name : {"sphere-hole.toml", "torus-floor.toml", "thesis-camera.toml"}) {
    INFO(name);
    const SceneDesc scene = exampleScene(name);
    Renderer<float> f(scene, sized(64, 64, 2));
    Renderer<double> d(scene, sized(64, 64, 2));
    const RgbImage a = renderImage(f), b = renderImage(d);
    // Interiors agree to rounding (a step of 1 in 8 bits); a few silhouette
    // and shadow-edge pixels may flip where float's roots land on the other
    // side of an edge.
    long far = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
      int delta = 0;
      for (std::size_t c = 0; c < 3; ++c) delta = std::max(delta, std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])));
      if (delta > 2) ++far;
    }
    const auto diff = lattice::testing::compareImages(a, b);
    INFO("pixels off by more than 2: " << far << "; mean squared error " << diff.meanSquaredError);
    REQUIRE(far <= 64 * 64 / 100);
    REQUIRE(diff.meanSquaredError < 2.0);
  }
}

TEST_CASE("renderer: bad sizes and thread counts are usage errors") {
  const SceneDesc scene = exampleScene("thesis-camera.toml");
  REQUIRE_THROWS_AS(Renderer<double>(scene, sized(-1, 10, 1)).width(), Error);
  REQUIRE_THROWS_AS(Renderer<double>(scene, sized(10, 100000, 1)).width(), Error);
  REQUIRE_THROWS_AS(Renderer<double>(scene, sized(10, 10, 1000)).width(), Error);
  Renderer<double> ok(scene, sized(8, 8, 1));
  std::vector<Color18> tooShort(4);
  REQUIRE_THROWS_AS(ok.row(0, tooShort), Error);
  std::vector<Color18> row(8);
  REQUIRE_THROWS_AS(ok.row(8, row), Error);
}

TEST_CASE("renderer: the three example scenes match their 96x96 goldens") {
  // Tolerance: goldens are rendered in double; other compilers/libms may move
  // a root by an ulp and flip a few edge pixels or nudge a value by 1.
  const lattice::testing::ImageTolerance tolerance{3, 30};
  for (const char* name : {"sphere-hole", "torus-floor", "thesis-camera"}) {
    INFO(name);
    Renderer<double> r(exampleScene(std::string(name) + ".toml"), sized(96, 96, 2));
    lattice::testing::checkGoldenPng(std::string("render/") + name + ".png", renderImage(r), tolerance);
  }
}

TEST_CASE("renderer: image row 0 is the top of the thesis camera's display") {
  // thesis-camera.toml: black sky, a floor y < -1 below a blue sphere at
  // (0, 0, 4) lit from the upper left (-x, +y).
  Renderer<double> r(exampleScene("thesis-camera.toml"), sized(33, 33, 1));
  const Vec3d sky = r.pixel(0, 0);
  const Vec3d floor = r.pixel(0, 32);
  const Vec3d centre = r.pixel(16, 16);
  REQUIRE(sky == Vec3d(0.0));  // the background
  REQUIRE(floor.r > 0.1);      // the floor is at the bottom, not the top
  REQUIRE(centre.b > centre.r);  // the blue sphere in the middle
  // The upper-left of the sphere faces the stronger light: brighter than its lower right.
  const Vec3d upperLeft = r.pixel(11, 11), lowerRight = r.pixel(21, 21);
  REQUIRE(upperLeft.b > lowerRight.b);
}
