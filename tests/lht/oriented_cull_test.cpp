// The oriented-box cull of a union's BVH leaves (render/accel/oriented_cull.hpp)
// over lattice leaves: every item it drops is one the leaf itself answers
// nothing for, the lanes (AVX2, SSE2) and the scalar reference drop the same items,
// the chords the cull hands a kept leaf are the leaf's own (firstEnterClipped
// and anyHitClipped answer as firstEnter and anyHit do), and a scene renders the same pixels with the
// cull off, scalar or in lanes.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <random>

#include "lht/leaf/lattice_leaf.hpp"
#include "lht/raster/lattice_object.hpp"
#include "tests/lht/raster_support.hpp"
#include "tests/lht/scene_render_support.hpp"
#include "tests/support/hair_scene.hpp"

using namespace lattice;
using namespace lattice::lht;
using lattice::testing::rasterizeObject;

namespace {

// Sets the cull path for one scope; the default (Auto) after it.
struct ForcedCull {
  explicit ForcedCull(CullPath path) { setCullPath(path); }
  ~ForcedCull() { setCullPath(CullPath::Auto); }
};

// Whether the leaf answers anything for the ray over (tmin, tmax).
template <typename T>
bool answers(const Primitive<T>& leaf, const Ray<T>& ray, T tmin, T tmax) {
  SpanList<T> spans;
  leaf.spans(ray, tmin, tmax, spans);
  Hit<T> hit;
  bool inside = false;
  return !spans.empty() || leaf.firstHit(ray, tmin, tmax, hit) || leaf.firstEnter(ray, tmin, tmax, hit, inside) ||
         inside || leaf.anyHit(ray, tmin, tmax);
}

template <typename T>
void checkCull() {
  const auto lht = rasterizeObject(capsuleObject(0.3, 2.0), 0.4, 2.0);
  // Four placements, one per lane, and a fifth position without a box.
  std::vector<PrimitivePtr<T>> leaves;
  for (int n = 0; n < 4; ++n) {
    const Mat4d place = glm::translate(Mat4d(1.0), Vec3d(0.3 * n, -0.2, 0.1 * n)) *
                        glm::rotate(Mat4d(1.0), 0.7 + 0.4 * n, glm::normalize(Vec3d(1, 1, n))) *
                        glm::scale(Mat4d(1.0), Vec3d(1.0, 1.5, 0.8));
    leaves.push_back(makeLatticeLeaf<T>(lht, place, 5, true, nullptr, LatticeLookup::Thesis));
  }
  std::vector<OrientedBox<T>> boxes(5);
  std::vector<bool> has(5, false);
  for (int n = 0; n < 4; ++n) has[std::size_t(n)] = leaves[std::size_t(n)]->orientedBox(boxes[std::size_t(n)]);
  REQUIRE(has[0]);
  const auto make = [&](CullPath path) {
    const ForcedCull forced(path);
    return OrientedCull<T>(boxes, has);
  };
  const OrientedCull<T> portable = make(CullPath::Portable), lanes = make(CullPath::Lanes), none = make(CullPath::None);
  const bool haveLanes =
      activeCullPath() == CullPath::Lanes && (!std::is_same_v<T, double> || doubleLanesRun());  // Auto here
  if (!haveLanes) WARN("no lanes for this arithmetic on this CPU: the lanes are compared only where they run");

  std::mt19937 rng(29);
  std::uniform_real_distribution<double> box(-1.5, 2.5), dir(-1.0, 1.0);
  int culled = 0, keptAnswering = 0, enteredFromChord = 0;
  for (int i = 0; i < 6000; ++i) {
    const Vec3d from(box(rng), box(rng), box(rng));
    Vec3d d(dir(rng), dir(rng), dir(rng));
    if (i % 7 == 0) d.y = 0.0;  // parallel to a world plane now and then
    if (i % 11 == 0) d = Vec3d(0.0, 0.0, 1.0);
    const Ray<T> ray{Vec3<T>(from), Vec3<T>(d)};
    const T tmin = T(i % 5 == 0 ? 0.3 : 1e-6), tmax = T(i % 3 == 0 ? 0.7 : 1e6);
    LaneChords<T> scalarChords, laneChords;
    const unsigned scalar = portable.keep(0, 4, ray, tmin, tmax, &scalarChords);
    REQUIRE(scalarChords.written == scalar);
    REQUIRE(none.keep(0, 4, ray, tmin, tmax, &laneChords) == 15u);
    REQUIRE(laneChords.written == 0u);  // no cull, no chords
    if (haveLanes) {
      REQUIRE(lanes.keep(0, 4, ray, tmin, tmax, &laneChords) == scalar);
      REQUIRE(laneChords.written == scalar);
      for (unsigned k = 0; k < 4; ++k) {
        if (!(scalar >> k & 1u)) continue;
        const LocalChord<T> a = laneChords.at(k), b = scalarChords.at(k);
        REQUIRE(std::memcmp(&a, &b, sizeof a) == 0);  // bit for bit
      }
    }
    for (unsigned k = 0; k < 4; ++k) {
      if (!(scalar >> k & 1u)) continue;
      const LocalChord<T> chord = scalarChords.at(k);
      Hit<T> own, given;
      bool ownInside = false, givenInside = false;
      const bool ownFound = leaves[k]->firstEnter(ray, tmin, tmax, own, ownInside);
      REQUIRE(leaves[k]->firstEnterClipped(ray, chord, tmin, tmax, given, givenInside) == ownFound);
      REQUIRE(givenInside == ownInside);
      REQUIRE(leaves[k]->anyHitClipped(ray, chord, tmin, tmax) == leaves[k]->anyHit(ray, tmin, tmax));
      if (ownFound) {
        ++enteredFromChord;
        REQUIRE(std::memcmp(&own.t, &given.t, sizeof own.t) == 0);
        REQUIRE(std::memcmp(&own.normal, &given.normal, sizeof own.normal) == 0);
      }
    }
    REQUIRE((portable.keep(1, 4, ray, tmin, tmax) & 8u) == 8u);  // position 4 has no box: always kept
    for (unsigned k = 0; k < 4; ++k) {
      const bool answered = answers<T>(*leaves[k], ray, tmin, tmax);
      if (!(scalar >> k & 1u)) {
        ++culled;
        REQUIRE_FALSE(answered);
      } else if (answered) {
        ++keptAnswering;
      }
    }
  }
  // Not vacuous: many culls, and many kept items that do answer.
  CHECK(culled > 5000);
  CHECK(keptAnswering > 500);
  CHECK(enteredFromChord > 300);
}

template <typename T>
RgbImage renderHair(CullPath path) {
  const ForcedCull forced(path);
  testing::HairScene hair;
  hair.size = 48;
  hair.hairs = 300;
  hair.floor = true;
  return testing::renderLatticeScene<T>(hair.toml(), "hair.toml");
}

}  // namespace

TEST_CASE("oriented cull: drops only what a lattice leaf answers nothing for, in lanes as in the scalar reference") {
  SECTION("double") { checkCull<double>(); }
  SECTION("float") { checkCull<float>(); }
}

TEST_CASE("oriented cull: a hair scene's pixels are the same with the cull off, scalar and in lanes") {
  const RgbImage off = renderHair<double>(CullPath::None);
  REQUIRE(off.width == 48);
  CHECK(renderHair<double>(CullPath::Portable).rgb == off.rgb);
  CHECK(renderHair<double>(CullPath::Auto).rgb == off.rgb);
  const RgbImage floatOff = renderHair<float>(CullPath::None);
  CHECK(renderHair<float>(CullPath::Portable).rgb == floatOff.rgb);
  CHECK(renderHair<float>(CullPath::Auto).rgb == floatOff.rgb);
}
