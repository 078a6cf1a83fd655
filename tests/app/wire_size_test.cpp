// The size search of a wire budget (app/wire_size.hpp): the largest
// picture at the scene's aspect whose stream fits with at least the floor,
// against the truecolour render at each size, with every size rendered for
// real (a Renderer at that size) and encoded by the real driver.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>

#include "app/wire_size.hpp"
#include "devices/device_table.hpp"
#include "tests/support/example_scene.hpp"

using namespace lattice;

namespace {

struct SizeRun {
  app::SizeArea area;
  app::WireSizeSearch result;
  int renders = 0;
};

SizeRun searchSizes(const char* scene, int areaWidth, int areaHeight, std::uint64_t bytes, double floor) {
  const SceneDesc desc = testing::loadExampleScene(scene);
  SizeRun run;
  run.area = app::sizeAreaFor(desc.options.width, desc.options.height, areaWidth, areaHeight);
  const app::RenderAt renderAt = [&](int width, int height) {
    ++run.renders;
    Renderer<double> renderer = testing::makeTestRenderer(desc, width, height);
    return renderImage(renderer);
  };
  app::WireBudget budget;
  budget.bytes = bytes;
  run.result = app::searchWireSize(renderAt, run.area, floor, devices::makeDevice("tek4125", {}), budget, {}, false);
  return run;
}

}  // namespace

TEST_CASE("wire size: the area is the largest picture at the scene's aspect, and the scene's own size is tried first") {
  const app::SizeArea wide = app::sizeAreaFor(640, 480, 1280, 1024);
  CHECK(wide.maxWidth == 1280);
  CHECK(wide.maxHeight == 960);
  CHECK(wide.startWidth == 640);
  const app::SizeArea square = app::sizeAreaFor(512, 512, 1280, 1024);
  CHECK(square.maxWidth == 1024);
  CHECK(square.maxHeight == 1024);
  const app::SizeArea large = app::sizeAreaFor(2000, 1000, 1280, 1024);  // fitted to the area first
  CHECK(large.startWidth == 1280);
  CHECK(large.startHeight == 640);
}

TEST_CASE("wire size: the largest size reaching the floor is chosen, and a size a step larger does not reach it") {
  const double floor = 30.0;
  const SizeRun run = searchSizes("sphere-hole.toml", 192, 192, 2500, floor);
  const app::WireSizeSearch& s = run.result;
  INFO(app::describeWireSize(s, run.area));
  REQUIRE(s.reachedFloor);
  const app::WireChoice& c = s.search.choice;
  CHECK(c.fits);
  CHECK(c.bytes <= 2500);
  CHECK(c.psnr >= floor);
  CHECK(c.width == c.height);  // the scene's aspect
  CHECK(c.width <= 192);
  CHECK(s.search.reference.width == c.width);  // scored against the render at that size
  CHECK(run.renders == int(s.tried.size()));
  // Every size tried above the one chosen missed the floor, and the nearest
  // such is within the search's tolerance; every size below reached it.
  int nearestAbove = 1 << 30;
  for (const app::SizeTried& t : s.tried) {
    if (t.width > c.width) {
      CHECK((!t.fits || t.psnr < floor));
      nearestAbove = std::min(nearestAbove, t.width);
    }
  }
  if (c.width < 192) CHECK(nearestAbove <= int(std::ceil(c.width * 1.04)) + 1);
}

TEST_CASE("wire size: when no size reaches the floor, the most accurate fitting picture is sent and said so") {
  const SizeRun run = searchSizes("sphere-hole.toml", 64, 64, 600, 60.0);
  const app::WireSizeSearch& s = run.result;
  const std::string said = app::describeWireSize(s, run.area);
  INFO(said);
  CHECK_FALSE(s.reachedFloor);
  CHECK_THAT(said, Catch::Contains("no size from 64x64 down reaches 60.0 dB"));
  for (const app::SizeTried& t : s.tried)
    if (t.fits) CHECK(t.psnr <= s.search.choice.psnr);
}
