// The shadow-ray occluder cache (render/scene/occluder_cache.hpp) on the hair
// scene with a floor and two lights: the cache answers every shadow ray as
// the scene's own anyHit does, rays in a row's order and random segments
// alike; a union's occluder() names a child that blocks the ray itself; and
// the renderer's rows (which ask the cache) equal pixels shaded with no
// cache, on one thread and on three.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "loader/lattice_scene_loader.hpp"
#include "render/renderer.hpp"
#include "render/scene/occluder_cache.hpp"
#include "tests/support/hair_scene.hpp"

using namespace lattice;

namespace {

lht::SceneWithLattices hairSceneWithFloor(int size) {
  testing::HairScene hair;
  hair.size = size;
  hair.floor = true;
  hair.fillLight = true;
  hair.fur = true;
  lht::TableSettings tables;
  tables.progress = false;
  return lht::parseSceneWithLattices(hair.toml(), "occluder-cache.toml", tables);
}

// The lighting model the renderer builds from a scene, for shading with no cache.
template <typename T>
LightingModel<T> lightingOf(const SceneDesc& scene) {
  LightingModel<T> model;
  model.ambient = Vec3<T>(scene.options.ambient);
  model.attenuationK = static_cast<T>(scene.options.attenuationK);
  for (const auto& light : scene.lights) model.lights.push_back(light.template cast<T>());
  for (const auto& m : scene.materials) model.materials.push_back(m.material.template cast<T>());
  return model;
}

// Every pixel's shadow rays in row order, as the renderer makes them.
template <typename T>
std::vector<std::pair<Ray<T>, std::size_t>> rowOrderShadowRays(const Renderer<T>& renderer, std::size_t lights,
                                                               const SceneDesc& scene) {
  const T scale = static_cast<T>(std::min(1.0, viewingDistance(scene.camera)));
  std::vector<std::pair<Ray<T>, std::size_t>> rays;
  for (int y = 0; y < renderer.height(); ++y)
    for (int x = 0; x < renderer.width(); ++x) {
      const Ray<T> primary = renderer.camera().primaryRay(x, y);
      Hit<T> hit;
      if (!renderer.root().firstHit(primary, T(0), std::numeric_limits<T>::infinity(), hit)) continue;
      const Vec3<T> point = primary.at(hit.t);
      const Vec3<T> n = dot(hit.normal, primary.direction) > T(0) ? -hit.normal : hit.normal;
      for (std::size_t i = 0; i < lights; ++i)
        rays.emplace_back(shadowRay(point, n, Vec3<T>(scene.lights[i].position), scale), i);
    }
  return rays;
}

template <typename T>
void cacheAnswersAsTheScene() {
  const lht::SceneWithLattices loaded = hairSceneWithFloor(48);
  RenderSettings settings;
  settings.threads = 1;
  const Renderer<T> renderer(loaded.scene, settings);
  const Primitive<T>& root = renderer.root();
  const std::size_t lights = loaded.scene.lights.size();

  auto rays = rowOrderShadowRays(renderer, lights, loaded.scene);
  // Random segments through the scene's box too, toward random lights.
  std::mt19937 rng(1988);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int k = 0; k < 4000; ++k) {
    const Vec3<T> from(T(u(rng)), T(u(rng)), T(u(rng)));
    const Vec3<T> to(T(u(rng)), T(u(rng)), T(u(rng)));
    rays.emplace_back(Ray<T>{from, to - from}, static_cast<std::size_t>(k) % lights);
  }

  OccluderCache<T> cache(lights);
  std::size_t blocked = 0, namedChild = 0;
  for (const auto& [ray, light] : rays) {
    const bool expected = root.anyHit(ray, T(0), T(1));
    REQUIRE(cache.blocked(root, ray, light) == expected);
    const Primitive<T>* who = root.occluder(ray, T(0), T(1));
    REQUIRE((who != nullptr) == expected);
    if (!who) continue;
    ++blocked;
    REQUIRE(who->anyHit(ray, T(0), T(1)));
    if (who != &root) ++namedChild;
  }
  // The scene must block many of them, and the root union hand its children down.
  CHECK(blocked > rays.size() / 10);
  CHECK(namedChild == blocked);
}

template <typename T>
void rowsEqualUncachedShading() {
  const lht::SceneWithLattices loaded = hairSceneWithFloor(40);
  const LightingModel<T> model = lightingOf<T>(loaded.scene);
  const T scale = static_cast<T>(std::min(1.0, viewingDistance(loaded.scene.camera)));
  const Vec3<T> background(loaded.scene.options.background);

  RenderSettings one;
  one.threads = 1;
  Renderer<T> renderer(loaded.scene, one);
  const Primitive<T>& root = renderer.root();
  std::vector<Vec3<T>> row(static_cast<std::size_t>(renderer.width()));
  std::size_t shadowed = 0;
  for (int y = 0; y < renderer.height(); ++y) {
    renderer.rowLinear(y, row);
    for (int x = 0; x < renderer.width(); ++x) {
      const Ray<T> primary = renderer.camera().primaryRay(x, y);
      Hit<T> hit;
      Vec3<T> expected = background;
      if (root.firstHit(primary, T(0), std::numeric_limits<T>::infinity(), hit)) {
        const Vec3<T> point = primary.at(hit.t);
        expected = shade(model, point, hit.normal, -primary.direction, hit.material,
                         [&](std::size_t i, const Vec3<T>& facing) {
                           const bool dark = inShadow(root, point, facing, model.lights[i].position, scale);
                           shadowed += dark ? 1 : 0;
                           return !dark;
                         });
      }
      INFO("pixel " << x << ", " << y);
      REQUIRE(row[static_cast<std::size_t>(x)] == expected);
    }
  }
  CHECK(shadowed > 0);

  RenderSettings three;
  three.threads = 3;
  Renderer<T> threaded(loaded.scene, three);
  const RgbImage a = renderImage(renderer), b = renderImage(threaded);
  REQUIRE(a.rgb == b.rgb);
}

}  // namespace

TEST_CASE("occluder cache: every shadow ray answered as the scene's anyHit answers it", "[occluder]") {
  SECTION("double") { cacheAnswersAsTheScene<double>(); }
  SECTION("float") { cacheAnswersAsTheScene<float>(); }
  SECTION("fixed point") { cacheAnswersAsTheScene<Fixed32>(); }
}

TEST_CASE("occluder cache: rendered rows equal shading with no cache, on 1 and 3 threads", "[occluder]") {
  SECTION("double") { rowsEqualUncachedShading<double>(); }
  SECTION("float") { rowsEqualUncachedShading<float>(); }
  SECTION("fixed point") { rowsEqualUncachedShading<Fixed32>(); }
}
