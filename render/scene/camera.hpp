#pragma once
// Primary rays. Two cameras:
//
// * The thesis camera (eq. 1.1, 1.2): the observer sits at o = (0, 0, -D)
//   looking down +z at a display W wide and H high centred on the origin
//   (the plane z = 0), made of Nx x Ny pixels. The ray through pixel (i, j)
//   is r = o + d t with
//       d = ( W (i / (Nx - 1) - 1/2),  H (j / (Ny - 1) - 1/2),  D ),
//   so t = 1 lands on the display and the corner pixels' centres lie on the
//   display's corners. +x is right and +y is up on the display.
//   Image rows run top-down (row y = 0 is the TOP row, as every RowSource18
//   and PNG expects), while the thesis's j grows upwards, so image pixel
//   (x, y) is thesis pixel (i, j) = (x, Ny - 1 - y).
//
// * A look-at camera: eye, target, up vector and vertical field of view; the
//   ray passes through the centre of pixel (x, y), row 0 at the top, and the
//   horizontal extent follows the image's aspect ratio.
//
// Camera set-up is done in double; rays come out in T.
#include <string>

#include "foundation/ray.hpp"
#include "foundation/vec.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

struct CameraDesc {
  enum class Kind { Thesis, LookAt };
  Kind kind = Kind::Thesis;
  // Thesis camera (eq. 1.2).
  double distance = 2.0;       // D
  double displayWidth = 1.0;   // W
  double displayHeight = 1.0;  // H
  // Look-at camera.
  Vec3d eye{0.0, 0.0, -5.0};
  Vec3d target{0.0, 0.0, 0.0};
  Vec3d up{0.0, 1.0, 0.0};
  double fovDegrees = 45.0;  // vertical
};

// Validates a description (positive sizes, non-degenerate look-at frame);
// throws lattice::Error(Input) naming `where` (e.g. "scene.toml: [camera]").
void validateCamera(const CameraDesc& camera, const std::string& where);

// How far the camera is from what it looks at: |target - eye| for look_at,
// the display distance D for the thesis camera. A length scale of the scene
// (the renderer sizes shadow-ray offsets with it).
double viewingDistance(const CameraDesc& camera);

template <typename T>
class Camera {
 public:
  // width, height: the image size in pixels (Nx, Ny), both >= 1.
  Camera(const CameraDesc& desc, int width, int height);

  // The ray through the centre of image pixel (x, y), row 0 at the top.
  Ray<T> primaryRay(int x, int y) const;
  // Where the observer is (the origin of every primary ray).
  const Vec3<T>& observer() const { return origin_; }

 private:
  Vec3<T> origin_{};
  // Direction of pixel (x, y) = corner_ + x * stepX_ + y * stepY_ (computed in
  // double, converted once per ray, so float and double agree to rounding).
  Vec3d corner_{};
  Vec3d stepX_{};
  Vec3d stepY_{};
  // Fixed point computes the direction in T itself (the per-pixel path must
  // not use double), from these copies converted once.
  Vec3<T> cornerT_{};
  Vec3<T> stepXT_{};
  Vec3<T> stepYT_{};
};

#define LATTICE_DECLARE(T) extern template class Camera<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_DECLARE)
#undef LATTICE_DECLARE

}  // namespace lattice
