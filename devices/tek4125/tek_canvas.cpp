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

void fillPolygon(IndexedImage& screen, std::span<const double> xy, PaletteIndex index) {
  const std::size_t n = xy.size() / 2;
  if (n < 3) return;
  double minY = xy[1], maxY = xy[1];
  for (std::size_t i = 1; i < n; ++i) {
    minY = std::min(minY, xy[2 * i + 1]);
    maxY = std::max(maxY, xy[2 * i + 1]);
  }
  const int rowFrom = std::max(0, static_cast<int>(std::ceil(minY - 0.5)));
  const int rowTo = std::min(screen.height - 1, static_cast<int>(std::floor(maxY - 0.5)));
  std::vector<double> crossings;
  for (int row = rowFrom; row <= rowTo; ++row) {
    const double yc = row + 0.5;
    crossings.clear();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
      if ((yi > yc) != (yj > yc)) crossings.push_back(xj + (yc - yj) * (xi - xj) / (yi - yj));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      const int from = std::max(0, static_cast<int>(std::ceil(crossings[k] - 0.5)));
      const int to = std::min(screen.width - 1, static_cast<int>(std::floor(crossings[k + 1] - 0.5)));
      for (int x = from; x <= to; ++x) *pixelAt(screen, x, row) = index;
    }
  }
}

}  // namespace lattice::tek
