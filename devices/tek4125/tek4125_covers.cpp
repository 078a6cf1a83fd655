#include "devices/tek4125/tek4125_covers.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include "devices/tek4125/tek4125_encoding.hpp"
#include "quantize/rate_distortion_runs.hpp"

namespace lattice::tek4125 {

namespace {

struct Sums {
  std::int64_t r = 0, g = 0, b = 0, squares = 0, pixels = 0;
  double shownError = 0;  // squared error of what the screen shows now
  Sums& operator+=(const Sums& o) {
    r += o.r, g += o.g, b += o.b, squares += o.squares, pixels += o.pixels, shownError += o.shownError;
    return *this;
  }
  Sums operator-(const Sums& o) const {
    return Sums{r - o.r, g - o.g, b - o.b, squares - o.squares, pixels - o.pixels, shownError - o.shownError};
  }
};

// The palette entry nearest a colour, remembered in a small direct-mapped
// table of 18-bit colours (a band's means repeat; a miss searches the
// palette, at most 256 entries), so its memory is fixed whatever the picture.
class NearestEntry {
 public:
  explicit NearestEntry(const Palette& palette) : palette_(palette), keys_(kSlots, kEmpty), values_(kSlots, 0) {}
  PaletteIndex operator()(Rgb8 c) {
    const Color18 key = packColor18(reduce8to6(c.r), reduce8to6(c.g), reduce8to6(c.b));
    const std::size_t slot = (key * 2654435761u) >> 20 & (kSlots - 1);  // Knuth's multiplicative hash
    if (keys_[slot] == key) return values_[slot];
    const Rgb8 q{expand6to8(red6(key)), expand6to8(green6(key)), expand6to8(blue6(key))};
    PaletteIndex best = 0;
    double bestError = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < palette_.size(); ++i)
      if (const double e = quantize::colourError(q, palette_[i]); e < bestError) bestError = e, best = PaletteIndex(i);
    keys_[slot] = key, values_[slot] = best;
    return best;
  }

 private:
  static constexpr std::size_t kSlots = 4096;
  static constexpr Color18 kEmpty = ~Color18{0};  // no 18-bit colour
  const Palette& palette_;
  std::vector<Color18> keys_;
  std::vector<PaletteIndex> values_;
};

void fill(std::vector<int>& shown, int width, const CoverRectangle& r) {
  for (int y = r.y0; y <= r.y1; ++y) std::fill_n(shown.begin() + long(y) * width + r.x0, r.x1 - r.x0 + 1, r.device);
}

class CoverPainter {
 public:
  CoverPainter(int width, bool fullXy, std::span<const PaletteIndex> pixels, const Palette& palette, int reserved,
               std::vector<int>& shown)
      : width_(width), fullXy_(fullXy), pixels_(pixels), palette_(palette), reserved_(reserved), shown_(shown),
        nearest_(palette) {}

  template <typename V>
  int at(const V& v, int x, int y) const {
    return int(v[std::size_t(y) * std::size_t(width_) + std::size_t(x)]);
  }

  // One band of rows y0..y1 (inclusive, image rows, 0 = top).
  void band(int y0, int y1, double lambda) {
    lambda_ = lambda;
    const int width = width_;
    // Cut points: columns whose band (targets and screen) differs from the previous column's.
    cuts_.assign(1, 0);
    for (int x = 1; x < width; ++x)
      for (int y = y0; y <= y1; ++y)
        if (at(pixels_, x, y) != at(pixels_, x - 1, y) || at(shown_, x, y) != at(shown_, x - 1, y)) {
          cuts_.push_back(x);
          break;
        }
    cuts_.push_back(width);
    const std::size_t cells = cuts_.size() - 1;
    prefix_.assign(cells + 1, Sums{});
    for (std::size_t c = 0; c < cells; ++c) {
      Sums s;
      for (int y = y0; y <= y1; ++y) {  // columns of a cell are alike: sum one, scale by its width
        const Rgb8 t = palette_[std::size_t(at(pixels_, cuts_[c], y))];
        s.r += t.r, s.g += t.g, s.b += t.b;
        s.squares += std::int64_t(t.r) * t.r + std::int64_t(t.g) * t.g + std::int64_t(t.b) * t.b;
        s.shownError += quantize::colourError(t, colourShown(palette_, at(shown_, cuts_[c], y), reserved_));
      }
      const int n = cuts_[c + 1] - cuts_[c];
      s.r *= n, s.g *= n, s.b *= n, s.squares *= n, s.shownError *= n;
      s.pixels = std::int64_t(n) * (y1 - y0 + 1);
      prefix_[c + 1] = prefix_[c];
      prefix_[c + 1] += s;
    }
    // best[k]: the least cost of cells [0, k); from[k] and colour[k] (-1: left alone) its last segment.
    std::vector<double> best(cells + 1, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> from(cells + 1, 0);
    std::vector<int> colour(cells + 1, -1);
    best[0] = 0;
    const double rectangle = 3 + (fullXy_ ? 10 : 8);  // ESC RR xy xy, the index added below
    for (std::size_t k = 1; k <= cells; ++k) {
      best[k] = best[k - 1] + (prefix_[k] - prefix_[k - 1]).shownError, from[k] = k - 1;
      const std::size_t first = k > std::size_t(kCoverWindow) ? k - std::size_t(kCoverWindow) : 0;
      for (std::size_t j = k; j-- > first;) {
        const Sums s = prefix_[k] - prefix_[j];
        const PaletteIndex c = nearest_(meanOf(s));
        const double bytes = rectangle + intLength(c + reserved_);
        const double total = best[j] + errorOf(s, palette_[c]) + lambda_ * bytes;
        if (total < best[k]) best[k] = total, from[k] = j, colour[k] = c;
      }
    }
    for (std::size_t k = cells; k > 0; k = from[k])
      if (colour[k] >= 0) paint(CoverRectangle{cuts_[from[k]], cuts_[k] - 1, y0, y1, colour[k] + reserved_});
  }

  std::vector<CoverRectangle> covers;

 private:
  static Rgb8 meanOf(const Sums& s) {
    auto channel = [&](std::int64_t sum) { return std::uint8_t((sum + s.pixels / 2) / s.pixels); };
    return Rgb8{channel(s.r), channel(s.g), channel(s.b)};
  }
  // sum over the pixels of |t - c|^2 = S2 - 2 c.S1 + n |c|^2, exact in integers.
  static double errorOf(const Sums& s, Rgb8 c) {
    const std::int64_t dot = c.r * s.r + c.g * s.g + c.b * s.b;
    const std::int64_t norm = std::int64_t(c.r) * c.r + std::int64_t(c.g) * c.g + std::int64_t(c.b) * c.b;
    return double(s.squares - 2 * dot + s.pixels * norm);
  }
  void paint(const CoverRectangle& r) {
    covers.push_back(r);
    fill(shown_, width_, r);
  }

  int width_;
  bool fullXy_;
  std::span<const PaletteIndex> pixels_;
  const Palette& palette_;
  int reserved_;
  std::vector<int>& shown_;
  NearestEntry nearest_;
  std::vector<int> cuts_;
  std::vector<Sums> prefix_;
  double lambda_ = 0;
};

}  // namespace

Rgb8 colourShown(const Palette& palette, int device, int reserved) {
  const int p = device < 0 ? 0 : device - reserved;  // the clear shows entry 0, which strict's TB sets
  return p >= 0 && std::size_t(p) < palette.size() ? palette[std::size_t(p)] : Rgb8{0, 0, 0};
}

std::vector<CoverRectangle> planCovers(int width, int height, bool fullXy, std::span<const PaletteIndex> pixels,
                                       const Palette& palette, int reserved, std::vector<int>& shown,
                                       std::span<const int> levels) {
  CoverPainter painter(width, fullXy, pixels, palette, reserved, shown);
  for (int rows : levels)
    for (int y0 = 0; y0 < height; y0 += rows) painter.band(y0, std::min(height, y0 + rows) - 1, kCoverLambdaPerRow * rows);
  return std::move(painter.covers);
}

void sendCovers(Tek4125Writer& out, const Tek4125RowLayout& layout, std::span<const CoverRectangle> covers,
                std::vector<int>& shown) {
  for (const CoverRectangle& r : covers) {
    const int top = layout.bottom + layout.height - 1 - r.y0;  // image row 0 is the top screen row
    out.command("RR");  // corners in screen pixels, lower-left then upper-right
    out.xy(layout.left + r.x0, top - (r.y1 - r.y0));
    out.xy(layout.left + r.x1, top);
    out.integer(r.device);
    fill(shown, layout.width, r);
  }
}

}  // namespace lattice::tek4125
