#pragma once
// Boxes for the BVH's tests: scattered in clusters (uneven splits), with a
// run of identical boxes no plane separates (the median split).
#include <random>
#include <vector>

#include "foundation/bounds.hpp"

namespace lattice::testing {

template <typename T>
std::vector<Bounds<T>> scatteredBoxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> cluster(-20, 20), spread(-1.5, 1.5), size(0.02, 0.3);
  std::vector<Bounds<T>> boxes;
  Vec3d centre(0.0);
  for (int i = 0; i < n; ++i) {
    if (i % 500 == 0) centre = Vec3d(cluster(rng), cluster(rng), cluster(rng));
    const Vec3d c = centre + Vec3d(spread(rng), spread(rng), spread(rng));
    const double r = size(rng);
    boxes.push_back({Vec3<T>(c - r), Vec3<T>(c + r)});
  }
  for (int i = 0; i < 300; ++i) boxes.push_back(boxes[7]);
  return boxes;
}

}  // namespace lattice::testing
