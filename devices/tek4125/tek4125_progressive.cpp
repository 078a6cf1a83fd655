#include "devices/tek4125/tek4125_progressive.hpp"

#include <algorithm>
#include <array>
#include <vector>

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

void drawRows(Tek4125RowPlanner& planner, std::span<const PaletteIndex> pixels, std::span<const PaletteIndex> rows,
              const Palette& palette, int reserved, std::span<int> shown) {
  const auto w = static_cast<std::size_t>(planner.width());
  const int height = static_cast<int>(pixels.size() / w);
  std::vector<int> row(w);
  for (int y : rowsByGain(pixels, shown, palette, reserved, int(w), height)) {
    const std::size_t at = std::size_t(y) * w;
    for (std::size_t x = 0; x < w; ++x) row[x] = rows[at + x] + reserved;
    const std::span<int> rowShown = shown.subspan(at, w);
    planner.row(y, row, rowShown);
    std::copy(row.begin(), row.end(), rowShown.begin());
  }
}

ProgressivePlan planProgressive(int width, int height, int background, bool fullXy,
                                std::span<const PaletteIndex> pixels, const Palette& palette, int reserved,
                                const quantize::RunCost& draftCost) {
  ProgressivePlan plan;
  std::vector<int> shown(pixels.size(), background);
  plan.covers = planCovers(width, height, fullXy, pixels, palette, reserved, shown);
  plan.drafts.assign(pixels.begin(), pixels.end());
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t at = 0; at < plan.drafts.size(); at += w)
    quantize::rateDistortionRow(std::span<PaletteIndex>(plan.drafts).subspan(at, w), palette, draftCost, kDraftLambda);
  return plan;
}

Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved, const ProgressivePlan& plan) {
  // What each pixel shows (-1: not known, the clear): the background RR's colour, then what each step drew.
  std::vector<int> shown(pixels.size(), layout.background);
  Tek4125RowStats stats;
  sendCovers(out, layout, plan.covers, shown);
  stats.rectangleFills += plan.covers.size();
  Tek4125DriverOptions rowOptions = options;
  rowOptions.mergeRows = false;  // rows do not come in order: each row's rectangles go at once
  Tek4125RowPlanner planner(out, layout, rowOptions);
  drawRows(planner, pixels, plan.drafts, palette, reserved, shown);
  drawRows(planner, pixels, pixels, palette, reserved, shown);
  planner.finish();
  const Tek4125RowStats& rows = planner.stats();
  stats.rasterWrites += rows.rasterWrites;
  stats.runLengthWrites += rows.runLengthWrites;
  stats.rectangleFills += rows.rectangleFills;
  stats.skippedPixels += rows.skippedPixels;
  return stats;
}

}  // namespace lattice::tek4125
