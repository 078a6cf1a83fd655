#pragma once
// Balls of one radius swept along a chain of centres: the form in which a
// capsule and a polyline state the space they fill, so bounds and covers
// that hold under any placement can be worked out without knowing which
// shape it was (lht/raster/object_cover.cpp, render/scene/instance_node.cpp).
#include <vector>

#include "foundation/vec.hpp"

namespace lattice {

struct BallChain {
  std::vector<Vec3d> centres;  // consecutive centres are joined by the swept ball
  double radius = 0.0;
};

}  // namespace lattice
