#pragma once
// What the devices' rate-distortion tests share: an example scene rendered and
// quantized, and a device's stream of a picture sent through
// quantize::RateDistortionSink at a lambda (0: the lossless stream).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <vector>

#include "devices/device.hpp"
#include "foundation/byte_sink.hpp"
#include "quantize/rate_distortion_runs.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/support/example_scene.hpp"

namespace lattice::testing {

inline std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in.good());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The example scene at width x height, median-cut to at most maxColors, no dither.
inline IndexedImage quantizedScene(const char* scene, int width, int height, int maxColors) {
  Renderer<double> renderer = makeTestRenderer(loadExampleScene(scene), width, height);
  quantize::PipelineOptions options;
  options.progress = false;
  IndexedImageSink sink(maxColors);
  quantize::runPipeline(renderer, sink, options);
  return sink.image();
}

// The device's stream of `picture`, its rows rewritten by rate-distortion runs at `lambda`.
inline std::vector<std::uint8_t> rateDistortionStream(const devices::Device& device, const IndexedImage& picture,
                                                      double lambda) {
  MemorySink out;
  auto driver = device.makeDriver(out);
  quantize::RateDistortionSink runs(driver->sink(), device.runCost, lambda);
  runs.begin(FrameInfo{picture.width, picture.height, picture.colormap});
  for (int y = 0; y < picture.height; ++y)
    runs.row(y, std::span<const PaletteIndex>(picture.pixels).subspan(std::size_t(y) * std::size_t(picture.width),
                                                                       std::size_t(picture.width)));
  runs.end();
  return out.data();
}

}  // namespace lattice::testing
