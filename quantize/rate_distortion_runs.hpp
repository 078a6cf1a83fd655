#pragma once
// Rate-distortion runs: a lossy step between the quantizer and a device
// driver that may give a pixel a neighbouring run's colour where the error
// is small and the bytes saved are many (the idea of lossy GIF encoders such
// as gifsicle's --lossy, applied to whatever runs a device sends).
//
// Method: per image row, a dynamic programme over the row's runs of equal
// index. A segment of consecutive runs may become one run of the colour of
// any run inside it; the programme picks the segmentation and colours that
// minimise
//     distortion + lambda * bytes,
// distortion being the summed squared 8-bit RGB error (over the three guns)
// between what each pixel is and the colour it gets, bytes being what the
// device says a run of that length and index costs on its wire (RunCost:
// each device supplies its own, devices/<device>/*_run_cost.*).
//
// What a pixel "is": given the truecolour picture (the quantizer's input),
// its true colour, which is what a budget's PSNR is scored against; then a
// segment may also take the palette entry nearest its mean true colour
// (sum |t - c|^2 = S2 - 2 c.S1 + n |c|^2, so from per-run sums any colour's
// error over a segment is O(1)), and a dithered picture's noise is smoothed
// where it costs bytes. Without it, the pixel's palette colour: runs only
// take colours already in the segment.
// lambda is "squared error a byte is worth". lambda = 0 leaves every row as
// it is (the lossless stream, byte for byte); larger lambda gives fewer,
// longer runs. The device's real encoder then encodes the result: the cost
// function only steers, it never decides a stream's size.
//
// Tunables: kWindowRuns, how many original runs one segment may span (cost
// O(runs * window^2) a row; 12 keeps Plate 6 at 512x512 under 0.1 s);
// kTruecolourWindowRuns, the same against the truecolour picture, where the
// cost is O(runs * window) (Plate 6's wire budgets: 12, 24, 40 and 80 runs
// within 0.15 dB of each other, 24 the best).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "foundation/indexed_image.hpp"
#include "foundation/rgb_image.hpp"
#include "foundation/scanline.hpp"

namespace lattice::quantize {

// Bytes a run of `length` pixels of palette index `index` costs on a
// device's wire (a fractional estimate is fine: 4-bit raster is 2/3 byte).
using RunCost = std::function<double(int length, int index)>;

// How a device makes its cost function for a picture (it may look at the
// whole picture: the 4125 and 4027 skip their most frequent colour).
using RunCostFactory = std::function<RunCost(const IndexedImage& picture)>;

inline constexpr int kWindowRuns = 12;
// Against the truecolour picture a segment has two candidate colours, not
// one a run, so it may span more runs for the same work.
inline constexpr int kTruecolourWindowRuns = 24;

// Rewrites one row in place. Rows are independent (no state between rows).
void rateDistortionRow(std::span<PaletteIndex> row, const Palette& palette, const RunCost& cost, double lambda);
// Every row of the picture; lambda <= 0 changes nothing.
void rateDistortionImage(IndexedImage& picture, const RunCost& cost, double lambda);
// The same, error measured against `truecolour` (the picture's size: else
// Error(Internal)) rather than the palette colours.
void rateDistortionImage(IndexedImage& picture, const RunCost& cost, double lambda, const RgbImage& truecolour);

// The index most pixels have (the first of equals): the colour the 4125 and
// 4027 paint once and then skip, so their runs of it cost nothing.
PaletteIndex mostFrequentIndex(const IndexedImage& picture);

// The squared RGB error of one pixel shown in colour b instead of a.
inline double colourError(Rgb8 a, Rgb8 b) {
  const double dr = double(a.r) - double(b.r), dg = double(a.g) - double(b.g), db = double(a.b) - double(b.b);
  return dr * dr + dg * dg + db * db;
}

// An IndexedSink in front of a driver: keeps the frame (a byte a pixel),
// and the truecolour rows when the quantizer offers them (3 bytes a pixel),
// and at end() asks the factory for the device's costs, rewrites every row
// (against the truecolour picture when every row of it came) and hands the
// frame on. With lambda <= 0 rows go straight through.
class RateDistortionSink final : public IndexedSink {
 public:
  RateDistortionSink(IndexedSink& next, RunCostFactory costs, double lambda);
  int maxColors() const override { return next_.maxColors(); }
  void begin(const FrameInfo& frame) override;
  void truecolourRow(int y, std::span<const Color18> colours) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  void end() override;

 private:
  IndexedSink& next_;
  RunCostFactory costs_;
  double lambda_;
  IndexedImage frame_;
  RgbImage truecolour_;
  int truecolourRows_ = 0;
};

}  // namespace lattice::quantize
