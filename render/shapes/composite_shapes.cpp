// The capsule: an exact swept ball, so lattice hairs (spheres joined by
// cylinders, thesis 3.4) have true surfaces and normals. Two forms: quartics
// joined by CSG (every arithmetic; the reference), and one closed-form leaf
// (capsule_leaf.cpp) that float and double use: 1.7-3x faster, measured in
// bench/results/2026-12-02-optimisation-steps.md.
#include "render/shapes/composite_shapes.hpp"

#include <type_traits>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "render/shapes/capsule_leaf.hpp"
#include "foundation/error.hpp"
#include "foundation/arithmetics.hpp"

namespace lattice {

namespace {

template <typename T>
Bounds<T> paddedBox(const Bounds<double>& objectBox, const Mat4d& objectToWorld, double pad) {
  Bounds<double> world = transformBounds(objectBox, objectToWorld);
  // Rounding to T moves a coordinate by up to one ulp of its magnitude.
  double magnitude = 0.0;
  for (int a = 0; a < 3; ++a) magnitude = std::max({magnitude, std::abs(world.lo[a]), std::abs(world.hi[a])});
  Vec3d grow(pad + 4.0 * double(std::numeric_limits<T>::epsilon()) * magnitude);
  return {Vec3<T>(world.lo - grow), Vec3<T>(world.hi + grow)};
}

}  // namespace

namespace {

void checkCapsule(double radius, double length) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw Error(ErrorKind::Input, fmt::format("capsule: radius must be a positive finite number, got {}", radius));
  if (!(length >= 0.0) || !std::isfinite(length))
    throw Error(ErrorKind::Input, fmt::format("capsule: length must be a finite number >= 0, got {}", length));
}

Bounds<double> capsuleBox(double radius, double length) {
  return {Vec3d(-radius, -radius, -radius), Vec3d(radius, radius, length + radius)};
}

double capsulePad(double radius, double length) { return 1e-5 * (radius + length); }  // covers rounding to T

}  // namespace

template <typename T>
PrimitivePtr<T> makeCapsule(double radius, double length, const Mat4d& objectToWorld, MaterialId material) {
  checkCapsule(radius, length);
  // Float and double take the closed form (capsule_leaf.hpp); fixed point
  // keeps the quartics, whose range checks it relies on.
  if constexpr (std::is_floating_point_v<T>)
    return makeCapsuleLeaf<T>(radius, length, objectToWorld,
                              paddedBox<T>(capsuleBox(radius, length), objectToWorld, capsulePad(radius, length)),
                              material);
  else
    return makeQuarticCapsule<T>(radius, length, objectToWorld, material);
}

template <typename T>
PrimitivePtr<T> makeQuarticCapsule(double radius, double length, const Mat4d& objectToWorld, MaterialId material) {
  checkCapsule(radius, length);
  const double pad = capsulePad(radius, length);
  QuarticShape ball = sphere(radius);
  const Mat4d farEnd = objectToWorld * glm::translate(Mat4d(1.0), Vec3d(0, 0, length));
  if (length == 0.0) return makeQuarticLeaf<T>(ball.f, ball.bounds, objectToWorld, material);

  // The body: the infinite cylinder between the planes z = 0 and z = length.
  QuarticShape tube = cylinder(radius);
  QuarticShape below = halfSpace(Vec3d(0, 0, -1), 0.0);    // z > 0
  QuarticShape above = halfSpace(Vec3d(0, 0, 1), length);  // z < length
  std::vector<PrimitivePtr<T>> body;
  body.push_back(makeQuarticLeaf<T>(tube.f, tube.bounds, objectToWorld, material));
  body.push_back(makeQuarticLeaf<T>(below.f, below.bounds, objectToWorld, material));
  body.push_back(makeQuarticLeaf<T>(above.f, above.bounds, objectToWorld, material));

  // Once rotated, each of those is unbounded, but the body and the capsule
  // are not: give the nodes their true boxes so a BVH of hairs can prune.
  Bounds<double> bodyBox{Vec3d(-radius, -radius, 0.0), Vec3d(radius, radius, length)};

  std::vector<PrimitivePtr<T>> parts;
  parts.push_back(makeCsgNode<T>(CsgOp::Intersection, std::move(body), paddedBox<T>(bodyBox, objectToWorld, pad)));
  parts.push_back(makeQuarticLeaf<T>(ball.f, ball.bounds, objectToWorld, material));
  parts.push_back(makeQuarticLeaf<T>(ball.f, ball.bounds, farEnd, material));
  return makeCsgNode<T>(CsgOp::Union, std::move(parts),
                        paddedBox<T>(capsuleBox(radius, length), objectToWorld, pad));
}

#define LATTICE_INSTANTIATE(T)                                                                  \
  template PrimitivePtr<T> makeCapsule<T>(double, double, const Mat4d&, MaterialId); \
  template PrimitivePtr<T> makeQuarticCapsule<T>(double, double, const Mat4d&, MaterialId);
LATTICE_FOR_EACH_ARITHMETIC(LATTICE_INSTANTIATE)
#undef LATTICE_INSTANTIATE

}  // namespace lattice
