// Rate-distortion runs on the 4125 (tek4125_run_cost.hpp with
// quantize/rate_distortion_runs.hpp): at lambda 0 the stream is the golden
// stream byte for byte (strict and compact); a vanishing lambda runs the
// whole dynamic programme and still changes no byte; a larger lambda gives a
// shorter stream whose emulated picture is exactly the rewritten frame.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "devices/device_table.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "devices/tek4125/tek4125_run_cost.hpp"
#include "foundation/byte_sink.hpp"
#include "quantize/rate_distortion_runs.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/support/example_scene.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/rate_distortion_stream.hpp"

using namespace lattice;
using namespace lattice::quantize;

using testing::quantizedScene;
using testing::rateDistortionStream;
using testing::readFileBytes;

TEST_CASE("rate-distortion runs: lambda 0 sends the golden 4125 streams byte for byte") {
  for (const char* forms : {"strict", "compact"})
    for (const char* scene : {"sphere-hole", "thesis-camera", "hook"}) {
      INFO(scene << " " << forms);
      const devices::Device device = devices::makeDevice("tek4125", {"planes=8", fmt::format("profile={}", forms)});
      REQUIRE(device.runCost);
      const IndexedImage picture = quantizedScene(fmt::format("{}.toml", scene).c_str(), 64, 64, 256);
      const std::string suffix = std::string(forms) == "strict" ? "" : "_compact";
      const auto golden = readFileBytes(testing::goldenPath(fmt::format("tek4125/scenes/{}_64x64_8planes{}.tek", scene, suffix)));
      CHECK(rateDistortionStream(device, picture, 0.0) == golden);
      CHECK(rateDistortionStream(device, picture, 1e-9) == golden);  // the programme ran, and kept every run
    }
}

TEST_CASE("rate-distortion runs: a larger lambda, a shorter 4125 stream showing exactly the rewritten frame") {
  for (const char* forms : {"strict", "compact"})
    for (int planes : {4, 8}) {
      INFO(forms << " " << planes << " planes");
      const devices::Device device =
          devices::makeDevice("tek4125", {fmt::format("planes={}", planes), fmt::format("profile={}", forms),
                                           "width=96", "height=72"});
      const IndexedImage picture = quantizedScene("torus-floor.toml", 96, 72, 1 << planes);
      std::size_t last = rateDistortionStream(device, picture, 0).size();
      for (double lambda : {2000.0, 20000.0}) {
        const auto bytes = rateDistortionStream(device, picture, lambda);
        INFO("lambda " << lambda << ": " << bytes.size() << " bytes, before " << last);
        CHECK(bytes.size() < last);
        last = bytes.size();
        IndexedImage expected = picture;
        rateDistortionImage(expected, device.runCost(picture), lambda);
        auto decoder = device.makeEmulator();
        decoder->feed(bytes);
        decoder->finish();
        CHECK(decoder->report().malformed == 0);
        const IndexedImage& screen = decoder->image();  // the screen is the picture's size: no placement
        long wrong = 0;
        for (int y = 0; y < picture.height; ++y)
          for (int x = 0; x < picture.width; ++x) {
            const Rgb8 want = expected.colorAt(x, y), got = screen.colorAt(x, y);
            wrong += std::abs(want.r - got.r) > 2 || std::abs(want.g - got.g) > 2 || std::abs(want.b - got.b) > 2;
          }
        CHECK(wrong == 0);
      }
    }
}

TEST_CASE("tek4125 run costs: the background costs at most a new span, RL codes grow with the run, raster where allowed") {
  IndexedImage picture(8, 1, 0);
  picture.colormap.assign(200, Rgb8{});
  picture.pixels = {5, 5, 5, 5, 5, 5, 7, 9};  // 5 the most frequent
  tek4125::Tek4125Profile strict;
  const RunCost cost = tek4125::tek4125RunCost(strict, picture);
  // Skipping the background inside a row costs a new span after it: strict's
  // ESC RH and five xy bytes, ESC RL and a count; a short run is cheaper as codes.
  CHECK(cost(1000, 5) == 12.0);
  CHECK(cost(1000, 7) > 12.0);
  CHECK(cost(1, 5) == cost(1, 7));
  CHECK(cost(1, 7) > 0.0);
  CHECK(cost(3, 7) < cost(4, 7));      // length * 256 + index: 2 bytes up to 3, then 3
  CHECK(cost(500, 7) > cost(100, 7));  // strict splits at 127 a code
  picture.colormap.resize(16);
  const RunCost fourBits = tek4125::tek4125RunCost(strict, picture);
  CHECK(fourBits(3, 7) <= 3 * 4 / 6.0);  // raster at 4 bits: 2/3 byte a pixel
}
