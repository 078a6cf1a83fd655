#include "quantize/rate_distortion_runs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "foundation/error.hpp"

namespace lattice::quantize {
namespace {

struct Run {
  int start = 0, length = 0;
  PaletteIndex index = 0;
};

// Squared errors between palette entries, looked up P*P times a row.
class ErrorTable {
 public:
  explicit ErrorTable(const Palette& palette) : size_(palette.size()), table_(size_ * size_) {
    for (std::size_t a = 0; a < size_; ++a)
      for (std::size_t b = 0; b < size_; ++b) table_[a * size_ + b] = colourError(palette[a], palette[b]);
  }
  double operator()(PaletteIndex a, PaletteIndex b) const { return table_[std::size_t(a) * size_ + b]; }

 private:
  std::size_t size_;
  std::vector<double> table_;
};

void smoothRow(std::span<PaletteIndex> row, const ErrorTable& error, const RunCost& cost, double lambda) {
  std::vector<Run> runs;
  for (std::size_t x = 0; x < row.size();) {
    std::size_t end = x + 1;
    while (end < row.size() && row[end] == row[x]) ++end;
    runs.push_back(Run{int(x), int(end - x), row[x]});
    x = end;
  }
  const std::size_t n = runs.size();
  if (n < 2) return;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> best(n + 1, kInf);
  std::vector<std::size_t> from(n + 1, 0);
  std::vector<PaletteIndex> colour(n + 1, 0);
  best[0] = 0;
  // Per candidate colour of the segment [j, k): its summed error there.
  std::vector<PaletteIndex> candidates;
  std::vector<double> distortion;
  for (std::size_t k = 1; k <= n; ++k) {
    candidates.clear();
    distortion.clear();
    int length = 0;
    const std::size_t first = k > std::size_t(kWindowRuns) ? k - std::size_t(kWindowRuns) : 0;
    for (std::size_t j = k; j-- > first;) {
      const Run& r = runs[j];
      length += r.length;
      for (std::size_t c = 0; c < candidates.size(); ++c) distortion[c] += r.length * error(r.index, candidates[c]);
      if (std::find(candidates.begin(), candidates.end(), r.index) == candidates.end()) {
        double d = 0;
        for (std::size_t i = j + 1; i < k; ++i) d += runs[i].length * error(runs[i].index, r.index);
        candidates.push_back(r.index);
        distortion.push_back(d);
      }
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const double total = best[j] + distortion[c] + lambda * cost(length, candidates[c]);
        if (total < best[k]) best[k] = total, from[k] = j, colour[k] = candidates[c];
      }
    }
  }
  for (std::size_t k = n; k > 0; k = from[k]) {
    const std::size_t j = from[k];
    const int start = runs[j].start, end = runs[k - 1].start + runs[k - 1].length;
    std::fill(row.begin() + start, row.begin() + end, colour[k]);
  }
}

}  // namespace

void rateDistortionRow(std::span<PaletteIndex> row, const Palette& palette, const RunCost& cost, double lambda) {
  if (lambda <= 0) return;
  smoothRow(row, ErrorTable(palette), cost, lambda);
}

void rateDistortionImage(IndexedImage& picture, const RunCost& cost, double lambda) {
  if (lambda <= 0) return;
  const ErrorTable error(picture.colormap);
  const auto width = static_cast<std::size_t>(picture.width);
  for (int y = 0; y < picture.height; ++y)
    smoothRow(std::span<PaletteIndex>(picture.pixels).subspan(std::size_t(y) * width, width), error, cost, lambda);
}

PaletteIndex mostFrequentIndex(const IndexedImage& picture) {
  std::vector<std::uint64_t> count(256, 0);
  for (PaletteIndex p : picture.pixels) ++count[p];
  return static_cast<PaletteIndex>(std::max_element(count.begin(), count.end()) - count.begin());
}

RateDistortionSink::RateDistortionSink(IndexedSink& next, RunCostFactory costs, double lambda)
    : next_(next), costs_(std::move(costs)), lambda_(lambda) {}

void RateDistortionSink::begin(const FrameInfo& frame) {
  if (lambda_ > 0) {
    frame_ = IndexedImage(frame.width, frame.height, 0);
    frame_.colormap = frame.palette;
  }
  next_.begin(frame);
}

void RateDistortionSink::row(int y, std::span<const PaletteIndex> indices) {
  if (lambda_ <= 0) return next_.row(y, indices);
  if (y < 0 || y >= frame_.height || indices.size() != std::size_t(frame_.width))
    throw Error(ErrorKind::Internal, fmt::format("rate-distortion runs: row {} of {} pixels for a {}x{} frame", y,
                                                 indices.size(), frame_.width, frame_.height));
  std::copy(indices.begin(), indices.end(), frame_.pixels.begin() + long(y) * frame_.width);
}

void RateDistortionSink::end() {
  if (lambda_ > 0) {
    rateDistortionImage(frame_, costs_(frame_), lambda_);
    const auto width = static_cast<std::size_t>(frame_.width);
    for (int y = 0; y < frame_.height; ++y)
      next_.row(y, std::span<const PaletteIndex>(frame_.pixels).subspan(std::size_t(y) * width, width));
  }
  next_.end();
}

}  // namespace lattice::quantize
