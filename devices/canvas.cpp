#include "devices/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace lattice::devices {
namespace {

// Products of two coordinates overflow 64 bits for the far-off points a
// stream may name; 128-bit intermediates keep every step exact.
__extension__ typedef __int128 Wide;

long floorDiv(Wide a, Wide b) {
  Wide q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return static_cast<long>(q);
}

// Step i of n along one coordinate: origin + i * delta / n, ties rounded away
// from the origin (the Bresenham walk's choice).
long stepAt(long i, long origin, long delta, long n) {
  const Wide twice = Wide{2} * i * delta;
  return delta >= 0 ? origin + floorDiv(twice + n, Wide{2} * n) : origin - floorDiv(-twice + n, Wide{2} * n);
}

}  // namespace

void drawLine(IndexedImage& screen, long x0, long y0, long x1, long y1, PaletteIndex index) {
  const long dx = x1 - x0, dy = y1 - y0;
  const long n = std::max(std::labs(dx), std::labs(dy));
  if (n == 0) {
    if (PaletteIndex* p = pixelAt(screen, x0, y0)) *p = index;
    return;
  }
  // The range of i whose coordinate can lie on the screen, widened by a step
  // each side so rounding never loses a visible point.
  long iLo = 0, iHi = n;
  auto restrict = [&](long origin, long delta, long lo, long hi) {
    if (delta == 0) {
      if (origin < lo || origin > hi) iHi = -1;
      return;
    }
    long a = floorDiv(Wide{lo - 1 - origin} * n, delta);
    long b = floorDiv(Wide{hi + 1 - origin} * n, delta);
    if (a > b) std::swap(a, b);
    iLo = std::max(iLo, a - 1);
    iHi = std::min(iHi, b + 1);
  };
  restrict(x0, dx, 0, screen.width - 1);
  restrict(y0, dy, 0, screen.height - 1);
  for (long i = iLo; i <= iHi; ++i)
    if (PaletteIndex* p = pixelAt(screen, stepAt(i, x0, dx, n), stepAt(i, y0, dy, n))) *p = index;
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

}  // namespace lattice::devices
