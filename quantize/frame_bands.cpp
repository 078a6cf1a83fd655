// The kept frame's histogram and mapping over bands of rows on every thread;
// the method and why are in frame_bands.hpp.
#include "quantize/frame_bands.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "foundation/error.hpp"
#include "foundation/threads.hpp"

namespace lattice::quantize {
namespace {

std::size_t rowsOf(int n) { return static_cast<std::size_t>(std::max(n, 0)); }

// Worker w's share [first, last) of n things cut into `workers` parts.
std::size_t shareStart(std::size_t n, unsigned w, unsigned workers) { return n * w / workers; }

}  // namespace

unsigned histogramWorkers(int height, unsigned threads) {
  const auto bands = std::max<std::size_t>(1, rowsOf(height) / static_cast<std::size_t>(kBandRows));
  return static_cast<unsigned>(std::min<std::size_t>(std::min(std::max(threads, 1u), kMostHistogramParts), bands));
}

std::size_t partialHistogramBytes(int height, unsigned threads, HistogramForm form) {
  return (histogramWorkers(height, threads) - 1) * Histogram::bytesOf(form);
}

std::size_t indexBandBytes(int width, unsigned threads, Dither dither) {
  if (threads <= 1 || dither == Dither::FloydSteinberg) return 0;
  return 2 * static_cast<std::size_t>(kBandRows) * rowsOf(width) * sizeof(PaletteIndex);
}

void countFrame(std::span<const Color18> frame, int width, Histogram& histogram, unsigned threads) {
  const std::size_t w = rowsOf(width), height = frame.size() / w;
  const unsigned workers = histogramWorkers(static_cast<int>(height), threads);
  std::vector<std::unique_ptr<Histogram>> parts(workers - 1);
  auto noStop = [] {};
  // Each part is made on its own thread: its 1 MiB is zeroed there, in parallel.
  runWorkers(
      workers,
      [&](unsigned t) {
        if (t > 0) parts[t - 1] = std::make_unique<Histogram>(histogram.form());
        Histogram& into = t == 0 ? histogram : *parts[t - 1];
        for (std::size_t y = shareStart(height, t, workers); y < shareStart(height, t + 1, workers); ++y)
          into.addRow(frame.subspan(y * w, w));
      },
      noStop);
  if (parts.empty()) return;
  if (histogram.form() == HistogramForm::Small) {
    for (const auto& part : parts) histogram.merge(*part);
    return;
  }
  runWorkers(
      workers,
      [&](unsigned t) {
        const auto first = static_cast<Color18>(shareStart(Histogram::kCells, t, workers));
        const auto last = static_cast<Color18>(shareStart(Histogram::kCells, t + 1, workers));
        for (const auto& part : parts) histogram.merge(*part, first, last);
      },
      noStop);
}

void mapFrame(std::span<const Color18> frame, int width, RowMapper& mapper, unsigned threads,
              const DeliverRow& deliver) {
  if (mapper.dither() == Dither::FloydSteinberg)
    throw Error(ErrorKind::Internal, "mapFrame: Floyd-Steinberg carries error between rows and maps on one thread");
  const std::size_t w = rowsOf(width);
  const int height = static_cast<int>(frame.size() / w);
  const int bands = (height + kBandRows - 1) / kBandRows;
  auto rowOf = [&](int y) { return frame.subspan(static_cast<std::size_t>(y) * w, w); };
  // Declared before the pool, so the pool (whose destructor waits for its work) goes first.
  std::array<std::vector<PaletteIndex>, 2> indices;
  for (auto& band : indices) band.resize(static_cast<std::size_t>(kBandRows) * w);
  WorkerPool pool(std::max(threads, 1u));
  const unsigned workers = pool.workers();
  auto startBand = [&](int band) {
    PaletteIndex* out = indices[static_cast<std::size_t>(band % 2)].data();
    pool.start(
        [&rowOf, &mapper, out, band, height, w, workers](unsigned t) {
          const int first = band * kBandRows, last = std::min(height, first + kBandRows);
          for (int y = first + static_cast<int>(t); y < last; y += static_cast<int>(workers))
            mapper.mapRow(y, rowOf(y), std::span<PaletteIndex>(out + static_cast<std::size_t>(y - first) * w, w));
        },
        [] {});
  };
  startBand(0);
  for (int band = 0; band < bands; ++band) {
    pool.wait();
    if (band + 1 < bands) startBand(band + 1);  // maps while this band goes to the sink
    const std::span<const PaletteIndex> out(indices[static_cast<std::size_t>(band % 2)]);
    for (int y = band * kBandRows; y < std::min(height, (band + 1) * kBandRows); ++y)
      deliver(y, rowOf(y), out.subspan(static_cast<std::size_t>(y - band * kBandRows) * w, w));
  }
}

}  // namespace lattice::quantize
