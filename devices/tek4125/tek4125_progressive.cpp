#include "devices/tek4125/tek4125_progressive.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "devices/tek4125/tek4125_covers.hpp"
#include "quantize/rate_distortion_runs.hpp"

namespace lattice::tek4125 {

std::vector<int> progressiveRowOrder(int height) {
  constexpr std::array<std::array<int, 2>, 4> kPasses = {{{0, 8}, {4, 8}, {2, 4}, {1, 2}}};  // first row, step
  std::vector<int> order;
  for (const auto& [first, step] : kPasses)
    for (int y = first; y < height; y += step) order.push_back(y);
  return order;
}

std::vector<int> rowsByGain(std::span<const PaletteIndex> pixels, std::span<const int> shown, const Palette& palette,
                            int reserved, int width, int height) {
  const auto w = static_cast<std::size_t>(width);
  std::vector<double> gain(static_cast<std::size_t>(height), 0);
  for (std::size_t y = 0; y < gain.size(); ++y) {
    double error = 0;
    int runs = 0;
    for (std::size_t x = 0; x < w; ++x) {
      const PaletteIndex p = pixels[y * w + x];
      error += quantize::colourError(palette[p], colourShown(palette, shown[y * w + x], reserved));
      if (x == 0 || p != pixels[y * w + x - 1]) ++runs;
    }
    gain[y] = error / (kRowHeaderBytes + kRunBytes * runs);
  }
  std::vector<int> order = progressiveRowOrder(height);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return gain[std::size_t(a)] > gain[std::size_t(b)]; });
  return order;
}

void drawRows(Tek4125RowPlanner& planner, std::span<const PaletteIndex> pixels, const Palette& palette, int reserved,
              std::span<int> shown, const quantize::RunCost& cost, double lambda) {
  const auto w = static_cast<std::size_t>(planner.width());
  const int height = static_cast<int>(pixels.size() / w);
  std::vector<PaletteIndex> draft(w);
  std::vector<int> row(w);
  for (int y : rowsByGain(pixels, shown, palette, reserved, int(w), height)) {
    const std::size_t at = std::size_t(y) * w;
    std::copy_n(pixels.begin() + long(at), w, draft.begin());
    if (lambda > 0) quantize::rateDistortionRow(draft, palette, cost, lambda);
    for (std::size_t x = 0; x < w; ++x) row[x] = draft[x] + reserved;
    const std::span<int> rowShown = shown.subspan(at, w);
    planner.row(y, row, rowShown);
    std::copy(row.begin(), row.end(), rowShown.begin());
  }
}

Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved, const quantize::RunCost& draftCost) {
  // What each pixel shows (-1: not known, the clear): the background RR's colour, then what each step drew.
  std::vector<int> shown(pixels.size(), layout.background);
  Tek4125RowStats stats;
  stats.rectangleFills += drawCovers(out, layout, pixels, palette, reserved, shown);
  Tek4125DriverOptions rowOptions = options;
  rowOptions.mergeRows = false;  // rows do not come in order: each row's rectangles go at once
  Tek4125RowPlanner planner(out, layout, rowOptions);
  drawRows(planner, pixels, palette, reserved, shown, draftCost, kDraftLambda);
  drawRows(planner, pixels, palette, reserved, shown, draftCost, 0);
  planner.finish();
  const Tek4125RowStats& rows = planner.stats();
  stats.rasterWrites += rows.rasterWrites;
  stats.runLengthWrites += rows.runLengthWrites;
  stats.rectangleFills += rows.rectangleFills;
  stats.skippedPixels += rows.skippedPixels;
  return stats;
}

}  // namespace lattice::tek4125
