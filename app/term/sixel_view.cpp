#include "app/term/sixel_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numeric>

#include "devices/sixel/sixel_driver.hpp"

namespace lattice::app {
namespace {

int distance2(const Rgb8& a, const Rgb8& b) {
  const int dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return dr * dr + dg * dg + db * db;
}

}  // namespace

SixelView::SixelView(const ViewGeometry& host, int screenWidth, int screenHeight)
    : host_(host), screenWidth_(screenWidth), screenHeight_(screenHeight) {
  const int areaWidth = std::min(kMaxViewWidth, std::max(1, host.columns * host.cellWidth));
  const int areaHeight = std::max(1, (host.rows - kTextRowsBelow) * host.cellHeight);
  // The largest scale <= 1 at which the whole screen fits, aspect kept.
  const double scale = std::min({1.0, static_cast<double>(areaWidth) / screenWidth,
                                 static_cast<double>(areaHeight) / screenHeight});
  width_ = std::max(1, static_cast<int>(screenWidth * scale));
  height_ = std::max(1, static_cast<int>(screenHeight * scale));
  bands_ = (height_ + host.cellHeight - 1) / host.cellHeight;
  sourceX_.resize(static_cast<std::size_t>(width_));
  sourceY_.resize(static_cast<std::size_t>(height_));
  for (int x = 0; x < width_; ++x)
    sourceX_[static_cast<std::size_t>(x)] =
        static_cast<int>(static_cast<long long>(x) * screenWidth / width_);
  for (int y = 0; y < height_; ++y)
    sourceY_[static_cast<std::size_t>(y)] =
        static_cast<int>(static_cast<long long>(y) * screenHeight / height_);
  view_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0);
}

void SixelView::scale(const IndexedImage& screen) {
  palette_ = screen.colormap;
  for (int y = 0; y < height_; ++y) {
    const PaletteIndex* from = screen.pixels.data() + static_cast<std::size_t>(sourceY_[static_cast<std::size_t>(y)]) *
                                                          static_cast<std::size_t>(screen.width);
    PaletteIndex* to = view_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
    for (int x = 0; x < width_; ++x) to[x] = from[sourceX_[static_cast<std::size_t>(x)]];
  }
}

std::string SixelView::update(const IndexedImage& screen) {
  scale(screen);
  const bool everything = !drawnAny_ || palette_ != drawnPalette_;
  std::string out;
  std::uint64_t bands = 0;
  const std::size_t bandPixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(host_.cellHeight);
  int runStart = -1;
  for (int band = 0; band <= bands_; ++band) {
    bool changed = false;
    if (band < bands_) {
      const std::size_t from = static_cast<std::size_t>(band) * bandPixels;
      const std::size_t to = std::min(view_.size(), from + bandPixels);
      changed = everything || !std::equal(view_.begin() + static_cast<std::ptrdiff_t>(from),
                                          view_.begin() + static_cast<std::ptrdiff_t>(to),
                                          drawn_.begin() + static_cast<std::ptrdiff_t>(from));
    }
    if (changed && runStart < 0) runStart = band;
    if (!changed && runStart >= 0) {
      out += drawBands(runStart, band);
      bands += static_cast<std::uint64_t>(band - runStart);
      runStart = -1;
    }
  }
  drawn_ = view_;
  drawnPalette_ = palette_;
  drawnAny_ = true;
  if (!out.empty()) {
    ++stats_.redraws;
    stats_.bytes += out.size();
    stats_.bandsDrawn += bands;
    stats_.lastBytes = out.size();
  }
  return out;
}

std::string SixelView::fullFrame(const IndexedImage& screen) {
  scale(screen);
  return drawBands(0, bands_);
}

std::string SixelView::drawBands(int first, int last) {
  const int top = first * host_.cellHeight;
  const int rows = std::min(height_, last * host_.cellHeight) - top;
  const std::size_t begin = static_cast<std::size_t>(top) * static_cast<std::size_t>(width_);
  const std::size_t end = begin + static_cast<std::size_t>(rows) * static_cast<std::size_t>(width_);
  // The colours these bands use, most used first, each given a register.
  std::array<std::uint64_t, 256> count{};
  for (std::size_t i = begin; i < end; ++i) ++count[view_[i]];
  std::vector<int> used;
  for (int i = 0; i < 256; ++i)
    if (count[static_cast<std::size_t>(i)] > 0) used.push_back(i);
  std::stable_sort(used.begin(), used.end(), [&](int a, int b) {
    return count[static_cast<std::size_t>(a)] > count[static_cast<std::size_t>(b)];
  });
  const int registers = std::clamp(host_.registers, 2, 256);
  const std::size_t kept = std::min(used.size(), static_cast<std::size_t>(registers));
  auto colour = [&](int index) {
    return static_cast<std::size_t>(index) < palette_.size() ? palette_[static_cast<std::size_t>(index)] : Rgb8{};
  };
  std::array<PaletteIndex, 256> reg{};
  FrameInfo frame;
  frame.width = width_;
  frame.height = rows;
  for (std::size_t k = 0; k < kept; ++k) {
    reg[static_cast<std::size_t>(used[k])] = static_cast<PaletteIndex>(k);
    frame.palette.push_back(colour(used[k]));
  }
  for (std::size_t k = kept; k < used.size(); ++k) {  // more colours than registers: the nearest kept one
    std::size_t best = 0;
    for (std::size_t j = 1; j < kept; ++j)
      if (distance2(colour(used[k]), frame.palette[j]) < distance2(colour(used[k]), frame.palette[best])) best = j;
    reg[static_cast<std::size_t>(used[k])] = static_cast<PaletteIndex>(best);
  }
  if (frame.palette.size() < 2) frame.palette.resize(2);  // the driver's smallest palette
  sixel::SixelProfile profile;
  profile.registers = registers;
  profile.width = width_;
  profile.height = std::max(rows, 1);
  MemorySink sink;
  sixel::SixelDriver driver(sink, profile);
  driver.begin(frame);
  std::vector<PaletteIndex> row(static_cast<std::size_t>(width_));
  for (int y = 0; y < rows; ++y) {
    const PaletteIndex* from = view_.data() + begin + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
    for (int x = 0; x < width_; ++x) row[static_cast<std::size_t>(x)] = reg[from[x]];
    driver.row(y, row);
  }
  driver.end();
  std::string out = fmt::format("\x1b[{};1H", first + 1);  // the band's text row
  out.append(sink.data().begin(), sink.data().end());
  return out;
}

IndexedImage SixelView::shown() const {
  IndexedImage image(width_, height_, drawnPalette_.size());
  image.pixels = drawn_;
  image.colormap = drawnPalette_;
  return image;
}

}  // namespace lattice::app
