// The quantizer's passes over a kept frame on 1..N threads
// (quantize/frame_bands.hpp), on a rendered picture; bench/quantize-bands.sh
// renders it and runs this program:
//
//   quantize_bands_bench [--runs N] [--threads "1 2"] PICTURE.png
//
// Method: the picture is read once into a frame of 18-bit colours. Each
// round times, for every thread count in turn (so a change in the machine's
// load hits each alike): the histogram (countFrame), the mapping with no
// dither and with Bayer (mapFrame, or the one-thread row loop at one thread:
// the inverse map's cells resolved as the rows need them, as in the
// pipeline) and the whole Frame-mode pipeline from frame to a sink that
// keeps nothing (runPipeline; median cut and the map's set-up included).
// Beside them, the histogram counted pixel by pixel through
// Histogram::add, which is what addRow did before it had a loop of its own.
// Wall and CPU milliseconds (CPU: every thread's), medians of --runs after
// one untimed round. Every thread count's indices are checked against the
// one-thread row loop's.
#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_main.hpp"
#include "foundation/error.hpp"
#include "foundation/rgb_image_source.hpp"
#include "io/png.hpp"
#include "quantize/frame_bands.hpp"
#include "quantize/histogram.hpp"
#include "quantize/inverse_colormap.hpp"
#include "quantize/median_cut.hpp"
#include "quantize/row_mapper.hpp"
#include "quantize/run_pipeline.hpp"

using namespace lattice;
using namespace lattice::quantize;

namespace {

double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

struct Sample {
  double wall = 0, cpu = 0;  // milliseconds
};

Sample timed(const std::function<void()>& work) {
  const auto wall = std::chrono::steady_clock::now();
  const double cpu = cpuNow();
  work();
  return {std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall).count(),
          (cpuNow() - cpu) * 1e3};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// Rows of an in-memory frame, for runPipeline.
class FrameSource final : public RowSource18 {
 public:
  FrameSource(const std::vector<Color18>& frame, int width) : frame_(frame), width_(width) {}
  int width() const override { return width_; }
  int height() const override { return static_cast<int>(frame_.size()) / width_; }
  void row(int y, std::span<Color18> out) override {
    std::copy_n(frame_.begin() + static_cast<std::ptrdiff_t>(y) * width_, width_, out.begin());
  }

 private:
  const std::vector<Color18>& frame_;
  int width_;
};

class NullSink final : public IndexedSink {
 public:
  int maxColors() const override { return 256; }
  void begin(const FrameInfo&) override {}
  void row(int, std::span<const PaletteIndex>) override {}
  void end() override {}
};

// The frame mapped with `threads` (1: the pipeline's row loop), into `out`.
void mapWith(const std::vector<Color18>& frame, int width, const Palette& palette, Dither dither, unsigned threads,
             std::vector<PaletteIndex>& out) {
  InverseColorMap map(palette);
  RowMapper mapper(map, width, dither);
  const auto w = static_cast<std::size_t>(width);
  if (threads <= 1) {
    for (std::size_t y = 0; y < frame.size() / w; ++y)
      mapper.mapRow(static_cast<int>(y), std::span<const Color18>(frame).subspan(y * w, w),
                    std::span<PaletteIndex>(out).subspan(y * w, w));
    return;
  }
  mapFrame(frame, width, mapper, threads, [&](int y, std::span<const Color18>, std::span<const PaletteIndex> row) {
    std::copy(row.begin(), row.end(), out.begin() + static_cast<std::ptrdiff_t>(y) * width);
  });
}

int run(int argc, char** argv) {
  int runs = 7;
  std::vector<unsigned> threadCounts{1, 2};
  std::string picture;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--threads" && i + 1 < argc) {
      threadCounts.clear();
      std::istringstream list(argv[++i]);
      for (unsigned t; list >> t;) threadCounts.push_back(std::max(t, 1u));
    } else {
      picture = arg;
    }
  }
  if (picture.empty() || threadCounts.empty())
    throw Error(ErrorKind::Usage, "usage: quantize_bands_bench [--runs N] [--threads \"1 2\"] PICTURE.png");
  const RgbImage image = io::readPng(picture);
  RgbImageSource source(image);
  std::vector<Color18> frame(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y)
    source.row(y, std::span<Color18>(frame).subspan(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width),
                                                    static_cast<std::size_t>(image.width)));
  Histogram reference;
  countFrame(frame, image.width, reference, 1);
  reference.finish();
  const Palette palette = medianCut(reference, 256, {});
  std::vector<PaletteIndex> expected(frame.size()), got(frame.size());
  mapWith(frame, image.width, palette, Dither::None, 1, expected);

  std::map<std::string, std::vector<Sample>> samples;  // by row name
  std::vector<std::string> order;
  auto record = [&](const std::string& name, Sample s, int round) {
    if (round < 0) return;  // the untimed round
    if (!samples.count(name)) order.push_back(name);
    samples[name].push_back(s);
  };
  for (int round = -1; round < runs; ++round) {
    record("histogram, pixel by pixel (Histogram::add), 1 thread", timed([&] {
             Histogram h;
             for (Color18 c : frame) h.add(c);
           }),
           round);
    for (unsigned t : threadCounts) {
      record(fmt::format("histogram (countFrame), {} thread(s)", t), timed([&] {
               Histogram h;
               countFrame(frame, image.width, h, t);
             }),
             round);
      for (Dither dither : {Dither::None, Dither::Bayer}) {
        record(fmt::format("map, dither {}, {} thread(s)", nameOfValue(kDitherNames, dither, "?"), t),
               timed([&] { mapWith(frame, image.width, palette, dither, t, got); }), round);
        if (dither == Dither::None && got != expected)
          throw Error(ErrorKind::Internal, fmt::format("{} threads mapped other indices than one", t));
      }
      record(fmt::format("pipeline, frame mode, {} thread(s)", t), timed([&] {
               FrameSource rows(frame, image.width);
               NullSink sink;
               PipelineOptions options;
               options.mode = PipelineMode::Frame;
               options.progress = false;
               options.threads = t;
               runPipeline(rows, sink, options);
             }),
             round);
    }
  }
  fmt::print("{}: {}x{}, {} distinct colours, {} rounds\n", picture, image.width, image.height,
             reference.distinctColors(), runs);
  fmt::print("| pass | wall ms (median) | CPU ms (median) |\n|---|---:|---:|\n");
  for (const std::string& name : order) {
    std::vector<double> wall, cpu;
    for (const Sample& s : samples[name]) wall.push_back(s.wall), cpu.push_back(s.cpu);
    fmt::print("| {} | {:.2f} | {:.2f} |\n", name, median(wall), median(cpu));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return bench::runBenchMain("quantize_bands_bench", [&] { return run(argc, argv); });
}
