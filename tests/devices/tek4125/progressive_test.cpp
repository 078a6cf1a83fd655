// The progressive 4125 stream (profile key progressive=on,
// tek4125_progressive.hpp): its final screen is the ordinary stream's,
// colour map included, under both form sets, at 4 and 8 planes, for every
// strategy; it stays clean (no malformed or unknown command); a strict
// progressive stream draws the same under every unsettled reading, as
// strict_forms_test.cpp asks of the ordinary one; and part-way it already shows a whole picture, closer to the final
// one than the ordinary stream at the same byte.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <set>

#include "devices/device_table.hpp"
#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_progressive.hpp"
#include "devices/tek4125/tek4125_strategy.hpp"
#include "foundation/byte_sink.hpp"
#include "io/image_metrics.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/devices/tek4125/readings_keys.hpp"
#include "tests/support/example_scene.hpp"

using namespace lattice;

namespace {

std::vector<std::uint8_t> render(const char* scene, int width, int height, std::vector<std::string> settings,
                                 quantize::Dither dither = quantize::Dither::None) {
  Renderer<double> renderer = testing::makeTestRenderer(testing::loadExampleScene(scene), width, height);
  settings.push_back(fmt::format("width={}", width));
  settings.push_back(fmt::format("height={}", height));
  const devices::Device device = devices::makeDevice("tek4125", settings);
  quantize::PipelineOptions options;
  options.progress = false;
  options.quantize.dither = dither;
  MemorySink out;
  auto driver = device.makeDriver(out);
  quantize::runPipeline(renderer, driver->sink(), options);
  return out.data();
}

// The screen after `count` bytes, under the profile `settings` and the
// emulator's `readings` (readings_keys.hpp).
IndexedImage screenAfter(const std::vector<std::uint8_t>& bytes, std::size_t count,
                         const std::vector<std::string>& settings, const std::vector<std::string>& readings = {}) {
  tek4125::Tek4125Profile profile;
  tek4125::applyOverrides(profile, settings);
  auto decoder = std::make_unique<tek4125::Tek4125Decoder>(profile, tek4125::test::readingsOf(readings));
  decoder->feed(std::span<const std::uint8_t>(bytes).subspan(0, count));
  decoder->finish();
  if (count == bytes.size()) {
    CHECK(decoder->report().malformed == 0);
    CHECK(decoder->report().unknownCommands == 0);
  }
  return decoder->image();
}

}  // namespace

TEST_CASE("progressive: rows interlaced as Adam7's, each row once") {
  for (int height : {1, 5, 8, 9, 61, 64}) {
    const std::vector<int> order = tek4125::progressiveRowOrder(height);
    REQUIRE(order.size() == std::size_t(height));
    CHECK(std::set<int>(order.begin(), order.end()).size() == std::size_t(height));
    CHECK(order.front() == 0);
  }
  const std::vector<int> order = tek4125::progressiveRowOrder(16);
  CHECK(order == std::vector<int>{0, 8, 4, 12, 2, 6, 10, 14, 1, 3, 5, 7, 9, 11, 13, 15});
}

TEST_CASE("progressive: the final screen is the ordinary stream's, every form set, depth and strategy") {
  struct Case {
    const char* scene;
    int width, height;
    quantize::Dither dither;
  };
  const Case cases[] = {{"torus-floor.toml", 80, 60, quantize::Dither::None},
                        {"sphere-hole.toml", 64, 64, quantize::Dither::FloydSteinberg},
                        {"hook.toml", 61, 67, quantize::Dither::None}};
  for (const Case& c : cases)
    for (const char* forms : {"strict", "compact"})
      for (int planes : {4, 8})
        for (const char* strategy : {"shortest", "plain", "spans"}) {
          INFO(c.scene << " " << forms << " " << planes << " planes, strategy " << strategy);
          std::vector<std::string> settings{fmt::format("profile={}", forms), fmt::format("planes={}", planes),
                                            fmt::format("strategy={}", strategy)};
          const auto ordinary = render(c.scene, c.width, c.height, settings, c.dither);
          settings.push_back("progressive=on");
          const auto progressive = render(c.scene, c.width, c.height, settings, c.dither);
          CHECK(progressive != ordinary);
          settings.push_back(fmt::format("width={}", c.width));
          settings.push_back(fmt::format("height={}", c.height));
          const IndexedImage a = screenAfter(ordinary, ordinary.size(), settings);
          const IndexedImage b = screenAfter(progressive, progressive.size(), settings);
          CHECK(a.pixels == b.pixels);
          CHECK(a.colormap == b.colormap);
        }
}

TEST_CASE("progressive: a quarter of the way in, the screen is nearer the final picture than row order's") {
  const std::vector<std::string> plain{"profile=strict", "width=128", "height=128"};
  std::vector<std::string> progressive = plain;
  progressive.push_back("progressive=on");
  const auto a = render("torus-floor.toml", 128, 128, plain);
  const auto b = render("torus-floor.toml", 128, 128, progressive);
  const RgbImage finalScreen = toRgbImage(screenAfter(a, a.size(), plain));
  const double rowOrder = io::compareRgb(finalScreen, toRgbImage(screenAfter(a, a.size() / 4, plain))).psnr;
  const double coarseFirst = io::compareRgb(finalScreen, toRgbImage(screenAfter(b, b.size() / 4, plain))).psnr;
  INFO("PSNR after 25% of the bytes: row order " << rowOrder << " dB, progressive " << coarseFirst << " dB");
  CHECK(coarseFirst > rowOrder + 3.0);
}

TEST_CASE("progressive: a strict progressive stream draws the same under every unsettled reading") {
  const std::vector<std::string> settings{"profile=strict", "progressive=on", "width=96", "height=72"};
  const auto bytes = render("torus-floor.toml", 96, 72, settings);
  const IndexedImage usual = screenAfter(bytes, bytes.size(), settings);
  for (const char* reading : {"rr-origin=viewport", "rh-origin=screen", "surface-planes=4", "power-up-map=ral-cgm"}) {
    INFO(reading);
    const IndexedImage other = screenAfter(bytes, bytes.size(), settings, {reading});
    long differing = 0;
    for (std::size_t i = 0; i < usual.pixels.size(); ++i)
      differing += !(usual.colormap[usual.pixels[i]] == other.colormap[other.pixels[i]]);
    CHECK(differing == 0);
  }
}
