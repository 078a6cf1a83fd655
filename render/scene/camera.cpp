#include "render/scene/camera.hpp"

#include <fmt/format.h>

#include <cmath>

#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

namespace {

bool finite(const Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void validateCamera(const CameraDesc& camera, const std::string& where) {
  auto fail = [&](const std::string& what) {
    throw Error(ErrorKind::Input, fmt::format("{}: {}", where, what));
  };
  if (camera.kind == CameraDesc::Kind::Thesis) {
    if (!(camera.distance > 0 && std::isfinite(camera.distance)))
      fail("the thesis camera's distance D must be a finite number > 0");
    if (!(camera.displayWidth > 0 && std::isfinite(camera.displayWidth)))
      fail("the thesis camera's display width W must be a finite number > 0");
    if (!(camera.displayHeight > 0 && std::isfinite(camera.displayHeight)))
      fail("the thesis camera's display height H must be a finite number > 0");
    return;
  }
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up))
    fail("look_at camera vectors must be finite");
  Vec3d forward = camera.target - camera.eye;
  if (glm::length(forward) < 1e-12) fail("look_at camera: eye and target must be different points");
  if (glm::length(camera.up) < 1e-12) fail("look_at camera: up must be a non-zero vector");
  // Up parallel to the viewing direction leaves "right" undefined.
  if (glm::length(glm::cross(glm::normalize(forward), glm::normalize(camera.up))) < 1e-6)
    fail("look_at camera: up must not be parallel to the viewing direction (target - eye)");
  if (!(camera.fovDegrees > 0 && camera.fovDegrees < 180))
    fail("look_at camera: fov (vertical, degrees) must be between 0 and 180, exclusive");
}

double viewingDistance(const CameraDesc& camera) {
  return camera.kind == CameraDesc::Kind::Thesis ? camera.distance : glm::length(camera.target - camera.eye);
}

template <typename T>
Camera<T>::Camera(const CameraDesc& desc, int width, int height) {
  if (width < 1 || height < 1)
    throw Error(ErrorKind::Usage, fmt::format("image size {}x{} is empty; width and height must be >= 1", width, height));
  if (desc.kind == CameraDesc::Kind::Thesis) {
    const double D = desc.distance, W = desc.displayWidth, H = desc.displayHeight;
    origin_ = Vec3<T>(Vec3d(0.0, 0.0, -D));
    // eq. 1.2b with j = Ny - 1 - y. A single pixel column/row looks through
    // the display's centre (i / (Nx - 1) would divide by zero).
    const double sx = width > 1 ? W / (width - 1) : 0.0;
    const double sy = height > 1 ? H / (height - 1) : 0.0;
    const double x0 = width > 1 ? -W / 2 : 0.0;
    const double yTop = height > 1 ? H / 2 : 0.0;
    corner_ = Vec3d(x0, yTop, D);
    stepX_ = Vec3d(sx, 0.0, 0.0);
    stepY_ = Vec3d(0.0, -sy, 0.0);
    cornerT_ = Vec3<T>(corner_);
    stepXT_ = Vec3<T>(stepX_);
    stepYT_ = Vec3<T>(stepY_);
    return;
  }
  // Look-at: an orthonormal frame; the image plane sits at distance 1.
  const Vec3d forward = glm::normalize(desc.target - desc.eye);
  const Vec3d right = glm::normalize(glm::cross(forward, desc.up));
  const Vec3d up = glm::cross(right, forward);
  const double halfH = std::tan(desc.fovDegrees * 0.5 * 3.14159265358979323846 / 180.0);
  const double halfW = halfH * static_cast<double>(width) / static_cast<double>(height);
  origin_ = Vec3<T>(desc.eye);
  stepX_ = right * (2.0 * halfW / width);
  stepY_ = -up * (2.0 * halfH / height);
  // Centre of pixel (0, 0): top-left corner plus half a step each way.
  corner_ = forward - right * halfW + up * halfH + 0.5 * stepX_ + 0.5 * stepY_;
  cornerT_ = Vec3<T>(corner_);
  stepXT_ = Vec3<T>(stepX_);
  stepYT_ = Vec3<T>(stepY_);
}

template <typename T>
Ray<T> Camera<T>::primaryRay(int x, int y) const {
  if constexpr (!kIsIeee<T>) {
    return {origin_, cornerT_ + stepXT_ * T(x) + stepYT_ * T(y)};
  } else {
    const Vec3d d = corner_ + static_cast<double>(x) * stepX_ + static_cast<double>(y) * stepY_;
    return {origin_, Vec3<T>(d)};
  }
}

#define LATTICE_INSTANTIATE(T) template class Camera<T>;
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
