// Rate-distortion runs on sixel (sixel_run_cost.hpp with
// quantize/rate_distortion_runs.hpp): at lambda 0, and at a vanishing lambda
// that runs the whole programme, the stream is the scene golden byte for
// byte; a larger lambda gives a shorter stream whose emulated picture is
// exactly the rewritten frame (registers are palette indices).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <fstream>
#include <iterator>

#include "devices/device_table.hpp"
#include "devices/sixel/sixel_run_cost.hpp"
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

TEST_CASE("sixel rate-distortion runs: lambda 0 sends the golden scene streams byte for byte") {
  struct Case {
    const char* scene;
    int width, height, registers;
  };
  for (const Case c : {Case{"sphere-hole", 64, 64, 16}, Case{"torus-floor", 80, 60, 256},
                       Case{"fuzzy-sphere-1000", 96, 96, 256}}) {
    INFO(c.scene << " at " << c.registers);
    const devices::Device device = devices::makeDevice("sixel", {fmt::format("registers={}", c.registers)});
    REQUIRE(device.runCost);
    const IndexedImage picture = quantizedScene(fmt::format("{}.toml", c.scene).c_str(), c.width, c.height, c.registers);
    const auto golden = readFileBytes(testing::goldenPath(
        fmt::format("sixel/scenes/{}_{}x{}_{}.six", c.scene, c.width, c.height, c.registers)));
    CHECK(rateDistortionStream(device, picture, 0.0) == golden);
    CHECK(rateDistortionStream(device, picture, 1e-9) == golden);  // the programme ran, and kept every run
  }
}

TEST_CASE("sixel rate-distortion runs: a larger lambda, a shorter stream showing exactly the rewritten frame") {
  for (int registers : {16, 256}) {
    INFO(registers << " registers");
    const devices::Device device = devices::makeDevice("sixel", {fmt::format("registers={}", registers)});
    const IndexedImage picture = quantizedScene("fuzzy-sphere-1000.toml", 128, 128, registers);
    std::size_t last = rateDistortionStream(device, picture, 0).size();
    for (double lambda : {200.0, 2000.0, 20000.0}) {
      const auto bytes = rateDistortionStream(device, picture, lambda);
      INFO("lambda " << lambda << ": " << bytes.size() << " bytes, before " << last);
      CHECK(bytes.size() < last);
      last = bytes.size();
      IndexedImage expected = picture;
      rateDistortionImage(expected, device.runCost(picture), lambda);
      CHECK(expected.pixels != picture.pixels);
      auto decoder = device.makeEmulator();
      decoder->feed(bytes);
      decoder->finish();
      CHECK(decoder->report().malformed == 0);
      CHECK(decoder->image().pixels == expected.pixels);
    }
  }
}

TEST_CASE("sixel run costs: the most frequent register is free, others pay their run and #i") {
  IndexedImage picture(8, 1, 0);
  picture.colormap.assign(200, Rgb8{});
  picture.pixels = {5, 5, 5, 5, 5, 5, 7, 123};
  const RunCost cost = sixel::sixelRunCost(picture);
  CHECK(cost(100, 5) == 0.0);
  CHECK(cost(1, 7) == 1.0 + 2.0);     // "@" and "#7"
  CHECK(cost(3, 7) == 3.0 + 2.0);     // "@@@"
  CHECK(cost(4, 7) == 3.0 + 2.0);     // "!4@"
  CHECK(cost(120, 123) == 5.0 + 4.0);  // "!120@" and "#123"
  CHECK(sixel::sixelRunBytes(9) == 3.0);
  CHECK(sixel::sixelRunBytes(10) == 4.0);
}
