#include <catch2/catch.hpp>

#include <filesystem>

#include "devices/apollo_sim/apollo_output.hpp"
#include "devices/apollo_sim/apollo_driver.hpp"
#include "devices/apollo_sim/gpr_display.hpp"
#include "io/png.hpp"
#include "tests/quantize/test_sources.hpp"
#include "tests/support/golden.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::quantize;
using namespace lattice::apollo;
using lattice::testing::FunctionSource;

namespace {

// A test pattern: eight colour bars over the top half, a grey ramp and a
// red-to-blue ramp below, and a diagonal of white. More colours than 16, so
// the 4-plane profile has to quantize hard.
Color18 testPattern(int x, int y, int width, int height) {
  if (x == y) return packColor18(63, 63, 63);
  if (y < height / 2) {
    int bar = x * 8 / width;
    return packColor18(bar & 4 ? 63u : 0u, bar & 2 ? 63u : 0u, bar & 1 ? 63u : 0u);
  }
  unsigned t = static_cast<unsigned>(x * 63 / (width - 1));
  if (y < 3 * height / 4) return packColor18(t, t, t);
  return packColor18(63u - t, static_cast<unsigned>(y % 8), t);
}

FunctionSource patternSource(int width, int height) {
  return FunctionSource(width, height, [=](int x, int y) { return testPattern(x, y, width, height); });
}

PipelineOptions quiet(Dither dither) {
  PipelineOptions options;
  options.progress = false;
  options.quantize.dither = dither;
  return options;
}

}  // namespace

TEST_CASE("the Apollo driver centres the picture and clears the border to black") {
  GprDisplay display;
  display.init(GprDisplayMode::Borrow, dn660Profile(8));
  ApolloDriver sink(display);
  CHECK(sink.maxColors() == 256);
  auto source = patternSource(101, 50);
  runPipeline(source, sink, quiet(Dither::None));
  CHECK(sink.originX() == (1024 - 101) / 2);
  CHECK(sink.originY() == (1024 - 50) / 2);
  CHECK_FALSE(display.acquired());  // end() released it
  IndexedImage screen = display.snapshot();
  CHECK(screen.colorAt(0, 0) == Rgb8{0, 0, 0});
  CHECK(screen.colorAt(1023, 1023) == Rgb8{0, 0, 0});
  // The diagonal's white pixel lands at the origin.
  CHECK(screen.colorAt(sink.originX(), sink.originY()) == Rgb8{255, 255, 255});
  CHECK(screen.colorAt(sink.originX() + 5, sink.originY() + 5) == Rgb8{255, 255, 255});
}

TEST_CASE("the Apollo driver refuses a picture larger than the screen") {
  GprDisplay display;
  display.init(GprDisplayMode::Borrow, dn660Profile(8));
  ApolloDriver sink(display);
  FunctionSource tooWide(1025, 2, [](int, int) { return Color18{0}; });
  CHECK_THROWS_AS(runPipeline(tooWide, sink, quiet(Dither::None)), Error);
}

TEST_CASE("a 4-plane DN660 gets at most 16 colours") {
  auto source = patternSource(64, 64);
  ApolloScreen result = renderToApollo(source, dn660Profile(4), quiet(Dither::None));
  CHECK(result.report.paletteSize <= 16);
  CHECK(result.screen.colormap.size() == 16);
  CHECK(*std::max_element(result.screen.pixels.begin(), result.screen.pixels.end()) < 16);
}

TEST_CASE("Apollo screens match the golden PNGs") {
  struct Case {
    const char* golden;
    ApolloProfile profile;
    Dither dither;
  };
  for (const Case& c : {Case{"apollo_sim/dn660_pattern.png", dn660Profile(8), Dither::None},
                        Case{"apollo_sim/dn660-4_pattern_fs.png", dn660Profile(4), Dither::FloydSteinberg},
                        Case{"apollo_sim/dn580_pattern_bayer.png", dn580Profile(), Dither::Bayer}}) {
    auto source = patternSource(320, 240);
    ApolloScreen result = renderToApollo(source, c.profile, quiet(c.dither));
    INFO(c.golden);
    lattice::testing::checkGoldenPng(c.golden, toRgbImage(result.screen));
  }
}

TEST_CASE("an Apollo screen saved as a PNG keeps the whole screen") {
  auto path = std::filesystem::path(LATTICE_BINARY_DIR) / "apollo_sink_test_out.png";
  auto source = patternSource(40, 30);
  writePng(path, renderToApollo(source, dn580Profile(), quiet(Dither::None)).screen);
  RgbImage back = readPng(path);
  CHECK(back.width == 1280);
  CHECK(back.height == 1024);
  std::filesystem::remove(path);
}
