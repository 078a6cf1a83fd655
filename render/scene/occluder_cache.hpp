#pragma once
// The shadow-ray occluder cache: for each light, the node that blocked the
// last shadow ray toward it, asked first for the next one.
//
// Method: a shadow ray asks only yes or no (Primitive::anyHit), and the
// shadow rays of neighbouring pixels toward one light are mostly blocked by
// the same thing (the sphere over the floor, one hair over the skin beside
// it). The node that answered yes last time (Primitive::occluder: a leaf,
// or the child of a union that a union hands down) is asked first; if it
// blocks this ray too, the answer is yes without the walk, and it is the
// walk's own answer, since a union answers yes when any child does. Else the
// walk answers, and the node it names (none, for an unblocked ray) replaces
// the cached one.
//
// One cache a row (Renderer::rowLinear), so no two threads share one; it
// changes no answer, so pictures do not depend on rows or threads.
// Every arithmetic but on the firmware (LATTICE_FIXED_POINT_ONLY), which asks
// the scene as before: its baked union builds its children per visit and can
// name only itself, so a miss would walk the whole union twice.
#include <cstddef>
#include <vector>

#include "foundation/ray.hpp"
#include "render/shapes/primitive.hpp"

namespace lattice {

template <typename T>
class OccluderCache {
 public:
  explicit OccluderCache(std::size_t lights) : last_(kCaches ? lights : 0, nullptr) {}

  // Does anything in `scene` cross `ray` for 0 < t < 1 (a shadow ray toward
  // light number `light`)? scene.anyHit's answer.
  bool blocked(const Primitive<T>& scene, const Ray<T>& ray, std::size_t light) {
    if constexpr (!kCaches) {
      return scene.anyHit(ray, T(0), T(1));
    } else {
      const Primitive<T>*& last = last_[light];
      if (last && last->anyHit(ray, T(0), T(1))) return true;
      // An unblocked ray empties the slot: the rays after it are mostly
      // unblocked too, and would each pay a test that fails.
      last = scene.occluder(ray, T(0), T(1));
      return last != nullptr;
    }
  }

 private:
#ifdef LATTICE_FIXED_POINT_ONLY
  static constexpr bool kCaches = false;
#else
  static constexpr bool kCaches = true;
#endif
  std::vector<const Primitive<T>*> last_;  // by light; null: none yet
};

}  // namespace lattice
