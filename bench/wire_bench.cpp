// wire_bench SCENE.toml [--size WxH] [--out DIR]
//
// The wire half of the trade (docs/trade.md, "On the wire"): the
// scene is rendered once (double, full ray trace, as bench/trade.sh's palette
// rows), then for each 4125 form set (strict, compact), palette size,
// dithering and rate-distortion lambda, the real driver writes its stream
// and the real emulator decodes it; the picture cut from the emulated screen
// is compared with the truecolour render. Writes DIR/wire.tsv:
//   profile colours dither lambda bytes s9600 s38400 psnr ssim
// then DIR/budget.tsv, the wire-budget search (app/wire_budget.hpp) for the
// issue's two targets (57,600 B and 76,800 B, strict), and DIR/progressive.tsv,
// the PSNR against the final screen after 10/25/50 % of the bytes for the
// ordinary and the progressive strict stream at 256 colours.
// bench/wire-trade.sh runs this and bench/plot_wire.py.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/wire_budget.hpp"
#include "bench/bench_main.hpp"
#include "devices/device_table.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/error.hpp"
#include "foundation/rgb_image_source.hpp"
#include "io/image_metrics.hpp"
#include "io/ssim.hpp"
#include "loader/lattice_scene_loader.hpp"
#include "quantize/rate_distortion_runs.hpp"
#include "quantize/run_pipeline.hpp"
#include "render/renderer.hpp"

namespace {

using namespace lattice;

const char* ditherName(quantize::Dither d) { return d == quantize::Dither::None ? "none" : "fs"; }

IndexedImage quantized(const RgbImage& reference, int colors, quantize::Dither dither) {
  RgbImageSource source(reference);
  IndexedImageSink sink(256);
  quantize::PipelineOptions options;
  options.mode = quantize::PipelineMode::Frame;
  options.maxColors = colors;
  options.quantize.dither = dither;
  options.progress = false;
  quantize::runPipeline(source, sink, options);
  return sink.image();
}

std::vector<std::uint8_t> encode(const devices::Device& device, const IndexedImage& picture) {
  MemorySink out;
  auto driver = device.makeDriver(out);
  app::sendPicture(picture, driver->sink());
  return out.data();
}

RgbImage screenAfter(const devices::Device& device, const std::vector<std::uint8_t>& bytes, std::size_t count) {
  auto decoder = device.makeEmulator();
  decoder->feed(std::span<const std::uint8_t>(bytes).subspan(0, count));
  decoder->finish();
  return toRgbImage(decoder->image());  // the screen is the picture's size (width=, height= set)
}

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  std::string scene, out = ".";
  int width = 512, height = 512;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--size" && i + 1 < args.size()) {
      if (std::sscanf(args[++i].c_str(), "%dx%d", &width, &height) != 2)
        throw Error(ErrorKind::Usage, "--size takes WxH, e.g. 512x512");
    } else if (args[i] == "--out" && i + 1 < args.size()) {
      out = args[++i];
    } else if (scene.empty()) {
      scene = args[i];
    } else {
      throw Error(ErrorKind::Usage, "usage: wire_bench SCENE.toml [--size WxH] [--out DIR]");
    }
  }
  if (scene.empty()) throw Error(ErrorKind::Usage, "usage: wire_bench SCENE.toml [--size WxH] [--out DIR]");
  std::filesystem::create_directories(out);

  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.build.fullRayTrace = true;
  lht::SceneWithLattices loaded = lht::loadSceneWithLattices(scene);
  Renderer<double> renderer(loaded.scene, settings);
  const RgbImage reference = renderImage(renderer);
  const std::string screen[] = {fmt::format("width={}", width), fmt::format("height={}", height)};

  std::ofstream table(std::filesystem::path(out) / "wire.tsv");
  table << "profile\tcolours\tdither\tlambda\tbytes\ts9600\ts38400\tpsnr\tssim\n";
  for (const char* profile : {"strict", "compact"}) {
    const devices::Device device =
        devices::makeDevice("tek4125", {fmt::format("profile={}", profile), screen[0], screen[1]});
    for (int colors : {256, 64, 32, 16, 8})
      for (quantize::Dither dither : {quantize::Dither::None, quantize::Dither::FloydSteinberg}) {
        const IndexedImage lossless = quantized(reference, colors, dither);
        const quantize::RunCost cost = device.runCost(lossless);
        for (double lambda : {0.0, 500.0, 2000.0, 8000.0, 32000.0, 128000.0}) {
          IndexedImage picture = lossless;
          quantize::rateDistortionImage(picture, cost, lambda, reference);
          const auto bytes = encode(device, picture);
          const RgbImage shown = screenAfter(device, bytes, bytes.size());
          const double psnr = io::compareRgb(reference, shown).psnr, ssim = io::meanSsim(reference, shown);
          const auto n = static_cast<double>(bytes.size());
          table << fmt::format("{}\t{}\t{}\t{:g}\t{}\t{:.2f}\t{:.2f}\t{:.2f}\t{:.4f}\n", profile, colors,
                               ditherName(dither), lambda, bytes.size(), n * 10 / 9600, n * 10 / 38400, psnr, ssim);
          std::fprintf(stderr, "%s %d %s %g: %zu B, %.2f dB\n", profile, colors, ditherName(dither), lambda,
                       bytes.size(), psnr);
        }
      }
  }

  std::ofstream budget(std::filesystem::path(out) / "budget.tsv");
  budget << "profile\tlimit\tfits\tcolours\tdither\tlambda\tbytes\tpsnr_sent\tpsnr_screen\tssim\tencodings\n";
  for (const char* profile : {"strict", "compact"}) {
    // As `lattice render --wire-bytes` does: the forms a budget turns on (strict's xy-short=on).
    std::vector<std::string> keys = {fmt::format("profile={}", profile), screen[0], screen[1]};
    for (const std::string& s : app::wireSettingsToAdd(devices::makeDevice("tek4125", keys), keys)) keys.push_back(s);
    const devices::Device device = devices::makeDevice("tek4125", keys);
    for (std::uint64_t limit : {std::uint64_t(57600), std::uint64_t(76800)}) {
      app::WireBudget b;
      b.bytes = limit;
      const app::WireSearch s = app::searchWireBudget(reference, device, b, {}, false);
      const auto bytes = encode(device, s.picture);
      const double onScreen = io::compareRgb(reference, screenAfter(device, bytes, bytes.size())).psnr;
      budget << fmt::format("{}\t{}\t{}\t{}\t{}\t{:g}\t{}\t{:.2f}\t{:.2f}\t{:.4f}\t{}\n", profile, limit,
                            s.choice.fits ? "yes" : "no", s.choice.colors, ditherName(s.choice.dither),
                            s.choice.lambda, s.choice.bytes, s.choice.psnr, onScreen, s.choice.ssim, s.encodings);
      std::fprintf(stderr, "budget %s %llu: %s\n", profile, static_cast<unsigned long long>(limit),
                   app::describeWireChoice(s).c_str());
    }
  }

  std::ofstream progressive(std::filesystem::path(out) / "progressive.tsv");
  progressive << "stream\tbytes\tpsnr_at_10\tpsnr_at_25\tpsnr_at_50\n";
  const IndexedImage full = quantized(reference, 256, quantize::Dither::None);
  for (const char* mode : {"off", "on"}) {
    const devices::Device device = devices::makeDevice(
        "tek4125", {"profile=strict", screen[0], screen[1], fmt::format("progressive={}", mode)});
    const auto bytes = encode(device, full);
    const RgbImage last = screenAfter(device, bytes, bytes.size());
    std::string row = fmt::format("{}\t{}", std::string(mode) == "on" ? "progressive" : "row order", bytes.size());
    for (int percent : {10, 25, 50})
      row += fmt::format("\t{:.2f}",
                         io::compareRgb(last, screenAfter(device, bytes, bytes.size() * std::size_t(percent) / 100)).psnr);
    progressive << row << "\n";
    std::fprintf(stderr, "%s\n", row.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return lattice::bench::runBenchMain("wire_bench", [&] { return run(argc, argv); });
}
