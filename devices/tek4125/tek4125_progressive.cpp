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

Tek4125RowStats drawProgressive(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                const Tek4125DriverOptions& options, std::span<const PaletteIndex> pixels,
                                const Palette& palette, int reserved) {
  const int width = layout.width, height = layout.height;
  const auto w = static_cast<std::size_t>(width);
  const int background = layout.background;  // device index, -1 when nothing is skipped
  auto screenRow = [&](int y) { return layout.bottom + height - 1 - y; };
  // What each pixel shows once the covers are drawn (-1: not known, the clear).
  std::vector<int> shown(w * static_cast<std::size_t>(height), background);
  Tek4125RowStats stats;

  const quantize::RunCost coverCost = [&](int, int index) {
    return index + reserved == background ? 0.0 : kRectangleBytes;
  };
  std::vector<PaletteIndex> cover(w);
  for (int y0 = 0; y0 < height; y0 += kBandRows) {
    const int y1 = std::min(height, y0 + kBandRows) - 1;
    const auto middle = static_cast<std::size_t>((y0 + y1) / 2);
    std::copy_n(pixels.begin() + static_cast<long>(middle * w), width, cover.begin());
    quantize::rateDistortionRow(cover, palette, coverCost, kCoverLambda);
    for (int x = 0; x < width;) {
      int end = x + 1;
      while (end < width && cover[std::size_t(end)] == cover[std::size_t(x)]) ++end;
      const int index = cover[std::size_t(x)] + reserved;
      if (index != background) {
        out.command("RR");  // corners in screen pixels, lower-left then upper-right
        out.xy(layout.left + x, screenRow(y1));
        out.xy(layout.left + end - 1, screenRow(y0));
        out.integer(index);
        ++stats.rectangleFills;
        for (int y = y0; y <= y1; ++y)
          std::fill_n(shown.begin() + static_cast<long>(std::size_t(y) * w + std::size_t(x)), end - x, index);
      }
      x = end;
    }
  }

  Tek4125DriverOptions rowOptions = options;
  rowOptions.mergeRows = false;  // rows do not come in order: each row's rectangles go at once
  Tek4125RowLayout plainLayout = layout;
  plainLayout.background = -1;
  Tek4125DriverOptions plainOptions = rowOptions;
  plainOptions.skipBackground = false;
  Tek4125RowPlanner skipping(out, layout, rowOptions), plain(out, plainLayout, plainOptions);
  std::vector<int> row(w);
  for (int y : progressiveRowOrder(height)) {
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
