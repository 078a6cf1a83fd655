#include "devices/tek4125/tek_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace lattice::tek {

void drawLine(IndexedImage& screen, int px0, int py0, int px1, int py1, PaletteIndex index) {
  const int dx = std::abs(px1 - px0), dy = -std::abs(py1 - py0);
  const int sx = px0 < px1 ? 1 : -1, sy = py0 < py1 ? 1 : -1;
  int err = dx + dy;
  for (;;) {
    if (PaletteIndex* p = pixelAt(screen, px0, py0)) *p = index;
    if (px0 == px1 && py0 == py1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      px0 += sx;
    }
    if (e2 <= dx) {
      err += dx;
      py0 += sy;
    }
  }
}

namespace {

// The screen rows a polygon's pixel centres may fall on (empty when to < from).
std::pair<int, int> polygonRows(const IndexedImage& screen, std::span<const double> xy) {
  const std::size_t n = xy.size() / 2;
  double minY = xy[1], maxY = xy[1];
  for (std::size_t i = 1; i < n; ++i) {
    minY = std::min(minY, xy[2 * i + 1]);
    maxY = std::max(maxY, xy[2 * i + 1]);
  }
  return {std::max(0, static_cast<int>(std::ceil(minY - 0.5))),
          std::min(screen.height - 1, static_cast<int>(std::floor(maxY - 0.5)))};
}

}  // namespace

std::uint64_t fillPolygonWork(const IndexedImage& screen, std::span<const double> xy) {
  const std::size_t n = xy.size() / 2;
  if (n < 3) return 0;
  const auto [rowFrom, rowTo] = polygonRows(screen, xy);
  if (rowTo < rowFrom) return 0;
  return static_cast<std::uint64_t>(rowTo - rowFrom + 1) * (n + static_cast<std::uint64_t>(screen.width));
}

void fillPolygon(IndexedImage& screen, std::span<const double> xy, PaletteIndex index) {
  const std::size_t n = xy.size() / 2;
  if (n < 3) return;
  const auto [rowFrom, rowTo] = polygonRows(screen, xy);
  // Per row, with d = crossing - 0.5 for each edge crossing the row's centre
  // line: sorting the crossings and filling ceil(d_k)..floor(d_k+1) for each
  // pair is the even-odd rule. Pixel x is in such a pair exactly when the
  // number of d < x is odd or some d == x, which a sweep over toggles finds
  // without sorting: O(points + width) a row, however many edges cross it.
  const auto width = static_cast<std::size_t>(screen.width);
  std::vector<std::uint8_t> toggle(width + 1), onEdge(width);
  for (int row = rowFrom; row <= rowTo; ++row) {
    const double yc = row + 0.5;
    std::fill(toggle.begin(), toggle.end(), std::uint8_t{0});
    std::fill(onEdge.begin(), onEdge.end(), std::uint8_t{0});
    bool any = false;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
      if ((yi > yc) == (yj > yc)) continue;
      const double d = (xj + (yc - yj) * (xi - xj) / (yi - yj)) - 0.5;
      const double below = std::floor(d);  // pixels from below + 1 on have d < x
      const double first = std::clamp(below + 1.0, 0.0, static_cast<double>(width));
      toggle[static_cast<std::size_t>(first)] ^= 1;
      if (below == d && d >= 0.0 && d < static_cast<double>(width)) onEdge[static_cast<std::size_t>(d)] = 1;
      any = true;
    }
    if (!any) continue;
    PaletteIndex* line = pixelAt(screen, 0, row);
    std::uint8_t inside = 0;
    for (std::size_t x = 0; x < width; ++x) {
      inside ^= toggle[x];
      if (inside | onEdge[x]) line[x] = index;
    }
  }
}

}  // namespace lattice::tek
