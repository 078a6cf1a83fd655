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

Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved) {
  const int width = layout.width, height = layout.height;
  const auto w = static_cast<std::size_t>(width);
  const int background = layout.background;  // device index, -1 when nothing is skipped
  // What each pixel shows once the covers are drawn (-1: not known, the clear).
  std::vector<int> shown(w * static_cast<std::size_t>(height), background);
  Tek4125RowStats stats;

  stats.rectangleFills += drawCovers(out, layout, pixels, palette, reserved, shown);

  Tek4125DriverOptions rowOptions = options;
  rowOptions.mergeRows = false;  // rows do not come in order: each row's rectangles go at once
  Tek4125RowLayout plainLayout = layout;
  plainLayout.background = -1;
  Tek4125DriverOptions plainOptions = rowOptions;
  plainOptions.skipBackground = false;
  Tek4125RowPlanner skipping(out, layout, rowOptions), plain(out, plainLayout, plainOptions);
  std::vector<int> row(w);
  for (int y : rowsByGain(pixels, shown, palette, reserved, width, height)) {
    bool skip = background >= 0 && options.skipBackground;
    for (std::size_t x = 0; x < w; ++x) {
      row[x] = pixels[std::size_t(y) * w + x] + reserved;
      if (row[x] == background && shown[std::size_t(y) * w + x] != background) skip = false;
    }
    (skip ? skipping : plain).row(y, row);
  }
  skipping.finish();
  plain.finish();
  for (const Tek4125RowPlanner* p : {&skipping, &plain}) {
    stats.rasterWrites += p->stats().rasterWrites;
    stats.runLengthWrites += p->stats().runLengthWrites;
    stats.rectangleFills += p->stats().rectangleFills;
    stats.skippedPixels += p->stats().skippedPixels;
  }
  return stats;
}

}  // namespace lattice::tek4125
