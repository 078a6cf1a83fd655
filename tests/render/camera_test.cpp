// Primary rays of the thesis camera (eq. 1.1-1.2) and the look-at camera.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/scene/camera.hpp"
#include "foundation/error.hpp"

using namespace lattice;

namespace {

CameraDesc thesisCamera(double D, double W, double H) {
  CameraDesc c;
  c.kind = CameraDesc::Kind::Thesis;
  c.distance = D;
  c.displayWidth = W;
  c.displayHeight = H;
  return c;
}

template <typename T>
void requireVec(const Vec3<T>& v, double x, double y, double z, double eps = 1e-12) {
  INFO("got (" << v.x << ", " << v.y << ", " << v.z << "), expected (" << x << ", " << y << ", " << z << ")");
  REQUIRE(std::abs(static_cast<double>(v.x) - x) <= eps);
  REQUIRE(std::abs(static_cast<double>(v.y) - y) <= eps);
  REQUIRE(std::abs(static_cast<double>(v.z) - z) <= eps);
}

}  // namespace

TEST_CASE("thesis camera: observer at minus D and eq. 1.2 rays for corner and centre pixels") {
  // Nx = 5, Ny = 3, D = 2, W = 4, H = 2. Image row 0 is the top, i.e. the
  // thesis's j = Ny - 1 = 2: d = (W (i/(Nx-1) - 1/2), H (j/(Ny-1) - 1/2), D).
  Camera<double> cam(thesisCamera(2.0, 4.0, 2.0), 5, 3);
  requireVec(cam.observer(), 0, 0, -2);
  requireVec(cam.primaryRay(0, 0).direction, -2.0, 1.0, 2.0);   // top-left: i = 0, j = 2
  requireVec(cam.primaryRay(4, 0).direction, 2.0, 1.0, 2.0);    // top-right
  requireVec(cam.primaryRay(0, 2).direction, -2.0, -1.0, 2.0);  // bottom-left: j = 0
  requireVec(cam.primaryRay(4, 2).direction, 2.0, -1.0, 2.0);   // bottom-right
  requireVec(cam.primaryRay(2, 1).direction, 0.0, 0.0, 2.0);    // centre
  requireVec(cam.primaryRay(1, 1).direction, -1.0, 0.0, 2.0);   // i = 1: 4 * (1/4 - 1/2)
  // t = 1 lands on the display plane z = 0 at the pixel's position.
  requireVec(cam.primaryRay(4, 0).at(1.0), 2.0, 1.0, 0.0);
}

TEST_CASE("thesis camera: float rays equal double rays to float precision") {
  Camera<float> f(thesisCamera(3.0, 1.5, 1.0), 7, 4);
  Camera<double> d(thesisCamera(3.0, 1.5, 1.0), 7, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 7; ++x) {
      const Vec3d e = d.primaryRay(x, y).direction;
      requireVec(f.primaryRay(x, y).direction, e.x, e.y, e.z, 1e-6);
    }
}

TEST_CASE("thesis camera: a single pixel looks through the display centre") {
  Camera<double> cam(thesisCamera(2.0, 4.0, 2.0), 1, 1);
  requireVec(cam.primaryRay(0, 0).direction, 0, 0, 2);
}

TEST_CASE("look-at camera: centre ray towards the target and corners spanning the vertical fov") {
  CameraDesc c;
  c.kind = CameraDesc::Kind::LookAt;
  c.eye = Vec3d(0, 0, 5);
  c.target = Vec3d(0, 0, 0);
  c.up = Vec3d(0, 1, 0);
  c.fovDegrees = 90.0;
  Camera<double> cam(c, 3, 3);
  requireVec(cam.observer(), 0, 0, 5);
  // Odd size: pixel (1, 1) is the image centre.
  requireVec(cam.primaryRay(1, 1).direction, 0, 0, -1);
  // fov 90: the image spans tan 45 = 1 up and down at distance 1; pixel
  // centres of a 3-pixel image sit at -2/3, 0, +2/3. Looking down -z with y
  // up, +x is to the right (right-handed world).
  requireVec(cam.primaryRay(0, 0).direction, -2.0 / 3, 2.0 / 3, -1);
  requireVec(cam.primaryRay(2, 2).direction, 2.0 / 3, -2.0 / 3, -1);
  // A wider image keeps the vertical fov and widens horizontally.
  Camera<double> wide(c, 6, 3);
  requireVec(wide.primaryRay(0, 1).direction, -2.0 * (1 - 1.0 / 6), 0, -1);
}

TEST_CASE("camera descriptions that cannot work are rejected with a message") {
  CameraDesc c = thesisCamera(0.0, 1.0, 1.0);
  REQUIRE_THROWS_WITH(validateCamera(c, "s.toml:3:1: [camera]"), Catch::Contains("s.toml:3:1") &&
                                                                      Catch::Contains("distance D"));
  CameraDesc l;
  l.kind = CameraDesc::Kind::LookAt;
  l.eye = l.target = Vec3d(1, 2, 3);
  REQUIRE_THROWS_WITH(validateCamera(l, "x"), Catch::Contains("eye and target"));
  l.target = Vec3d(1, 5, 3);  // looking straight up with up = +y
  REQUIRE_THROWS_WITH(validateCamera(l, "x"), Catch::Contains("parallel"));
  l.target = Vec3d(0, 0, 0);
  l.fovDegrees = 180;
  REQUIRE_THROWS_WITH(validateCamera(l, "x"), Catch::Contains("fov"));
  REQUIRE_THROWS_AS(Camera<float>(thesisCamera(1, 1, 1), 0, 10), Error);
}
