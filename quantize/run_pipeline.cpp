#include "quantize/run_pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "quantize/frame_bands.hpp"
#include "quantize/histogram.hpp"
#include "quantize/inverse_colormap.hpp"
#include "quantize/median_cut.hpp"
#include "quantize/row_mapper.hpp"
#include "foundation/error.hpp"
#include "foundation/palette_counts.hpp"
#include "foundation/progress.hpp"

namespace lattice::quantize {
namespace {

void checkOptions(const RowSource18& source, const IndexedSink& sink, const PipelineOptions& options) {
  if (source.width() < 1 || source.height() < 1)
    throw Error(ErrorKind::Input, fmt::format("nothing to quantize: the picture is {}x{} pixels", source.width(),
                                              source.height()));
  if (options.mode == PipelineMode::Sample && options.sampleStep < 1)
    throw Error(ErrorKind::Usage, fmt::format("--sample {} is out of range: give a step of 1 or more",
                                              options.sampleStep));
  if (options.maxColors < 0 || options.maxColors > 256)
    throw Error(ErrorKind::Usage, fmt::format("--colors {} is out of range: give 1 to 256", options.maxColors));
  if (sink.maxColors() < 1)
    throw Error(ErrorKind::Internal, fmt::format("the output device offers {} colours", sink.maxColors()));
}

int colorBudget(const IndexedSink& sink, const PipelineOptions& options) {
  int k = std::min(sink.maxColors(), 256);  // PaletteIndex is one byte
  if (options.maxColors > 0) k = std::min(k, options.maxColors);
  return k;
}

}  // namespace

std::string_view pipelineModeName(PipelineMode mode) { return nameOfValue(kPipelineModeNames, mode, "?"); }

PipelineReport pipelineBuffers(int width, int height, const PipelineOptions& options) {
  const auto w = static_cast<std::size_t>(std::max(width, 0));
  PipelineReport report;
  report.histogramBytes = Histogram::bytesOf(options.quantize.histogram);
  report.rowBytes = w * (sizeof(Color18) + sizeof(PaletteIndex));
  if (options.mode == PipelineMode::Frame) {
    report.frameBytes = w * static_cast<std::size_t>(std::max(height, 0)) * sizeof(Color18);
    report.histogramBytes += partialHistogramBytes(height, options.threads, options.quantize.histogram);
    report.rowBytes += indexBandBytes(width, options.threads, options.quantize.dither);
  }
  if (options.quantize.dither == Dither::FloydSteinberg) report.errorRowBytes = RowMapper::errorRowBytes(width);
  return report;
}

PipelineReport runPipeline(RowSource18& source, IndexedSink& sink, const PipelineOptions& options) {
  checkOptions(source, sink, options);
  const int width = source.width(), height = source.height();
  const auto w = static_cast<std::size_t>(width);
  PipelineReport report = pipelineBuffers(width, height, options);

  std::vector<Color18> row(w);
  std::vector<Color18> frame;  // Frame mode only
  const bool bandsOfFrame = options.mode == PipelineMode::Frame && options.threads > 1;
  Histogram histogram(options.quantize.histogram);
  {
    const int rowStep = options.mode == PipelineMode::Sample ? options.sampleStep : 1;
    const auto histogramRows = (static_cast<std::uint64_t>(height) + static_cast<std::uint64_t>(rowStep) - 1) /
                               static_cast<std::uint64_t>(rowStep);
    Progress progress("histogram", histogramRows, "rows");
    if (!options.progress) progress.setEnabled(false);
    if (options.mode == PipelineMode::Frame) frame.resize(w * static_cast<std::size_t>(height));
    for (long y = 0; y < height; y += rowStep) {  // long: y + a huge --sample must not overflow
      std::span<Color18> out = options.mode == PipelineMode::Frame
                                   ? std::span<Color18>(frame).subspan(static_cast<std::size_t>(y) * w, w)
                                   : std::span<Color18>(row);
      source.row(static_cast<int>(y), out);
      ++report.rowsRendered;
      if (options.mode == PipelineMode::Sample)
        histogram.addRowSampled(out, options.sampleStep);
      else if (!bandsOfFrame)
        histogram.addRow(out);  // while the renderer traces the rows ahead
      progress.advance();
    }
    progress.finish();
    if (bandsOfFrame) countFrame(frame, width, histogram, options.threads);
  }
  histogram.finish();
  report.distinctColors = histogram.distinctColors();

  FrameInfo info;
  info.width = width;
  info.height = height;
  info.palette = medianCut(histogram, colorBudget(sink, options), options.quantize);
  report.paletteSize = info.palette.size();
  // Every colour the histogram counted goes to the entry it maps to (no
  // dithering), so its counts give each entry's share of the mapped picture:
  // exactly when the histogram saw every row, and the sample's share after
  // --mode sample, which is the share the pass that chose the palette saw
  // (the firmware renders Plate 6 so: the driver then takes its
  // background from that pass and keeps no frame). Host and firmware run this
  // same rule with the same flags, so their streams stay byte for byte the
  // same. Not where a 32-bit count could have saturated.
  const bool countsKnown = options.quantize.dither == Dither::None &&
                           static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) < UINT32_MAX;
  auto* countsSink = dynamic_cast<PaletteCountsSink*>(&sink);
  std::vector<std::uint64_t> counts;
  if (countsKnown && countsSink && countsSink->wantsPaletteCounts()) {
    InverseColorMap nearest = InverseColorMap::uncached(info.palette);
    counts.assign(info.palette.size(), 0);
    histogram.forEach([&](Color18 c, std::uint32_t n) { counts[nearest.nearest(c)] += n; });
  }

  InverseColorMap map = options.quantize.histogram == HistogramForm::Full
                            ? InverseColorMap(info.palette, histogram.releaseStorage())
                            : InverseColorMap::uncached(info.palette);
  if (options.quantize.histogram == HistogramForm::Small) histogram.releaseStorage();
  RowMapper mapper(map, width, options.quantize.dither);
  std::vector<PaletteIndex> indices(w);

  if (!counts.empty()) countsSink->paletteCounts(counts);
  sink.begin(info);
  Progress progress("quantize", static_cast<std::uint64_t>(height), "rows");
  if (!options.progress) progress.setEnabled(false);
  auto deliver = [&](int y, std::span<const Color18> in, std::span<const PaletteIndex> mapped) {
    sink.truecolourRow(y, in);
    sink.row(y, mapped);
    progress.advance();
  };
  if (bandsOfFrame && options.quantize.dither != Dither::FloydSteinberg)
    mapFrame(frame, width, mapper, options.threads, deliver);
  else
    for (int y = 0; y < height; ++y) {
      std::span<const Color18> in;
      if (options.mode == PipelineMode::Frame) {
        in = std::span<const Color18>(frame).subspan(static_cast<std::size_t>(y) * w, w);
      } else {
        source.row(y, row);
        ++report.rowsRendered;
        in = row;
      }
      mapper.mapRow(y, in, indices);
      deliver(y, in, indices);
    }
  sink.end();
  progress.finish();
  return report;
}

}  // namespace lattice::quantize
