#include "devices/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
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


// The range of steps i in [0, n] of the line whose point can lie on the
// screen, widened by a step each side so rounding never loses a visible
// point; empty (hi < lo) when none can.
struct StepRange {
  long n, lo, hi;
};

StepRange visibleSteps(const IndexedImage& screen, long x0, long y0, long x1, long y1) {
  const long dx = x1 - x0, dy = y1 - y0;
  const long n = std::max(std::labs(dx), std::labs(dy));
  StepRange r{n, 0, n};
  if (n == 0) return r;
  auto restrict = [&](long origin, long delta, long lo, long hi) {
    if (delta == 0) {
      if (origin < lo || origin > hi) r.hi = -1;
      return;
    }
    long a = floorDiv(Wide{lo - 1 - origin} * n, delta);
    long b = floorDiv(Wide{hi + 1 - origin} * n, delta);
    if (a > b) std::swap(a, b);
    r.lo = std::max(r.lo, a - 1);
    r.hi = std::min(r.hi, b + 1);
  };
  restrict(x0, dx, 0, screen.width - 1);
  restrict(y0, dy, 0, screen.height - 1);
  return r;
}

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

// Steps i, i + 1, ... of n along one coordinate: origin + i * delta / n,
// ties rounded away from the origin (the Bresenham walk's choice), that is
// origin +- floor((2 i |delta| + n) / 2n). The division is done once: the
// numerator grows by 2 |delta| a step and |delta| <= n, so the quotient
// grows by at most one a step, a carry.
// (A 128-bit division a step made 1 MB streams of long vectors break the
// bound docs/limits.md promises; bench/tek4014-vectors.sh measures it.)
struct Stepper {
  long position, remainder, increment, modulus, sign;
  Stepper(long i, long origin, long delta, long n)
      : increment(2 * std::labs(delta)), modulus(2 * n), sign(delta >= 0 ? 1 : -1) {
    const Wide numerator = Wide{2} * i * std::labs(delta) + n;
    position = origin + sign * static_cast<long>(numerator / modulus);
    remainder = static_cast<long>(numerator % modulus);
  }
  void advance() {
    remainder += increment;
    if (remainder >= modulus) {
      remainder -= modulus;
      position += sign;
    }
  }
};

}  // namespace

void drawLine(IndexedImage& screen, long x0, long y0, long x1, long y1, PaletteIndex index) {
  const StepRange r = visibleSteps(screen, x0, y0, x1, y1);
  if (r.n == 0) {
    if (PaletteIndex* p = pixelAt(screen, x0, y0)) *p = index;
    return;
  }
  if (r.hi < r.lo) return;
  Stepper x(r.lo, x0, x1 - x0, r.n), y(r.lo, y0, y1 - y0, r.n);
  for (long i = r.lo; i <= r.hi; ++i, x.advance(), y.advance())
    if (PaletteIndex* p = pixelAt(screen, x.position, y.position)) *p = index;
}

std::uint64_t lineWork(const IndexedImage& screen, long x0, long y0, long x1, long y1) {
  const StepRange r = visibleSteps(screen, x0, y0, x1, y1);
  if (r.n == 0) return 1;
  return r.hi < r.lo ? 0 : static_cast<std::uint64_t>(r.hi - r.lo + 1);
}

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

}  // namespace lattice::devices
