#pragma once
// The pipeline's two passes over a kept frame (PipelineMode::Frame), on every
// thread: the histogram and the mapping to palette indices.
//
// Method. Histogram: the frame's rows are cut into one band a thread; each
// thread (at most 8) counts its band into a histogram of its own (the first
// into the pipeline's), and the parts are merged into the first: the full form by
// disjoint ranges of the 18-bit cube, one a thread; the small form, at most
// 64 KiB a part, on one. Counts are sums, so the palette is the one a single
// thread finds. Mapping: bands of kBandRows rows are mapped on a pool of
// threads (rows dealt out in turn) while the caller hands the band before to
// the sink in row order, so the device's driver, which must see its rows in
// order, runs beside the mapping of the next band. No dithering and Bayer
// map each pixel alone; Floyd-Steinberg carries its error from row to row
// and stays on one thread (mapFrame is not for it). The bands are fixed by
// the picture, the work of each row by the row alone, so the stream is the
// same byte for byte on any number of threads.
//
// Why: with the frame kept, these passes run after the trace, so on one
// thread they are a serial tail of the render (docs/architecture.md, "How
// the work is split"). The cost is memory: a 1 MiB full histogram for each
// part after the first and two bands of indices (partialHistogramBytes,
// indexBandBytes, which pipelineBuffers counts).
#include <cstddef>
#include <functional>
#include <span>

#include "foundation/scanline.hpp"
#include "quantize/histogram.hpp"
#include "quantize/row_mapper.hpp"

namespace lattice::quantize {

inline constexpr int kBandRows = 32;
// At most this many histograms count a frame: 7 MiB more at most, while the
// count of a 2048 x 2048 frame already takes under a millisecond in 8 parts.
inline constexpr unsigned kMostHistogramParts = 8;

// The threads that count a frame of `height` rows: no band under kBandRows
// rows, no more than kMostHistogramParts.
unsigned histogramWorkers(int height, unsigned threads);
// What the band passes hold beyond the one-thread pipeline's buffers.
std::size_t partialHistogramBytes(int height, unsigned threads, HistogramForm form);
std::size_t indexBandBytes(int width, unsigned threads, Dither dither);

// Adds every pixel of the frame (height rows of `width`) to the histogram.
void countFrame(std::span<const Color18> frame, int width, Histogram& histogram, unsigned threads);

// Maps every row of the frame and calls deliver(y, colours, indices) for
// y = 0, 1, ... in order, on the caller's thread. The mapper's dither must
// not be Floyd-Steinberg (lattice::Error(Internal)).
using DeliverRow = std::function<void(int y, std::span<const Color18>, std::span<const PaletteIndex>)>;
void mapFrame(std::span<const Color18> frame, int width, RowMapper& mapper, unsigned threads,
              const DeliverRow& deliver);

}  // namespace lattice::quantize
