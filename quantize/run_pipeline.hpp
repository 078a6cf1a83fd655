#pragma once
// The streaming pipeline: RowSource18 -> histogram -> median cut -> inverse
// colour map (+ dither) -> IndexedSink, the thesis's *model* -> quantizer ->
// display chain (Lewis 1988 sec. 3.3) as one process holding O(width) pixels.
//
// Modes (memory in docs/quantize.md):
//   TwoPass  render every row for the histogram, then render again to map.
//            Holds the 1 MiB histogram (reused as the inverse-map cache),
//            one row of Color18 (4 B/pixel), one index row (1 B/pixel) and,
//            with Floyd-Steinberg, one error row (12 B/pixel). Least memory.
//   Frame    render once into a 4 B/pixel frame and map from it. Fastest when
//            rendering is the expensive part. Same output as TwoPass.
//            With `threads` above 1 its histogram and (without
//            Floyd-Steinberg) its mapping run over bands of rows on that
//            many threads (quantize/frame_bands.hpp): the same output again,
//            for 1 MiB more a histogram band after the first (at most 7).
//   Sample   the histogram pass renders every Nth row and takes every Nth
//            column; the map pass renders all rows. ~1/N of the extra render
//            cost, but the palette comes from a subset, so the output may
//            differ from TwoPass (documented, not a bug).
#include <cstddef>
#include <string>

#include "foundation/scanline.hpp"
#include "quantize/quantize_options.hpp"

namespace lattice::quantize {

enum class PipelineMode { TwoPass, Frame, Sample };
// Their spellings (`--mode`).
inline constexpr std::array<EnumName<PipelineMode>, 3> kPipelineModeNames = {{
    {PipelineMode::TwoPass, "passes"},
    {PipelineMode::Frame, "frame"},
    {PipelineMode::Sample, "sample"},
}};

struct PipelineOptions {
  PipelineMode mode = PipelineMode::TwoPass;
  int sampleStep = 4;   // Sample mode: every Nth row and column (>= 1)
  int maxColors = 0;    // 0: what the sink can show; otherwise min(this, sink)
  QuantizeOptions quantize;
  bool progress = true;  // draw progress bars (only ever on a terminal)
  unsigned threads = 1;  // Frame mode's passes over bands (1: all on the caller's thread)
};

struct PipelineReport {
  std::size_t paletteSize = 0;
  std::size_t distinctColors = 0;  // in the histogram (the sample, in Sample mode)
  long rowsRendered = 0;           // RowSource18::row calls: the cost of re-rendering
  // Bytes of the pipeline's own buffers, the figures docs/quantize.md quotes.
  std::size_t histogramBytes = 0;
  std::size_t rowBytes = 0;       // the Color18 row + the index row
  std::size_t errorRowBytes = 0;  // Floyd-Steinberg only
  std::size_t frameBytes = 0;     // Frame mode only
  std::size_t totalBytes() const { return histogramBytes + rowBytes + errorRowBytes + frameBytes; }
};

// Quantizes the source to at most min(sink.maxColors(), options.maxColors)
// colours and streams it into the sink (begin, every row in order, end).
// lattice::Error(Input) for an empty source, Error(Usage) for bad options.
PipelineReport runPipeline(RowSource18& source, IndexedSink& sink, const PipelineOptions& options);

// The buffers runPipeline will hold for a width x height picture (the byte
// fields of its report, before it runs): what --memory-budget plans with.
PipelineReport pipelineBuffers(int width, int height, const PipelineOptions& options);

std::string_view pipelineModeName(PipelineMode mode);

}  // namespace lattice::quantize
