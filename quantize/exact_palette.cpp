#include "quantize/exact_palette.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

namespace lattice::quantize {

namespace {

constexpr std::uint32_t kSlots = 512;  // a power of two, twice the most colours asked
constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;

}  // namespace

std::optional<IndexedImage> exactPalette(const RgbImage& picture, int maxColors) {
  const int limit = std::clamp(maxColors, 1, 256);
  std::array<std::uint32_t, kSlots> keys;
  std::array<std::uint16_t, kSlots> slotColor{};
  keys.fill(kEmpty);
  std::vector<std::uint32_t> colors;  // packed, in the order met
  std::vector<std::uint64_t> counts;
  const std::size_t n = static_cast<std::size_t>(picture.width) * static_cast<std::size_t>(picture.height);
  if (n == 0 || picture.rgb.size() < 3 * n) return std::nullopt;  // the pipeline says what is wrong
  std::vector<std::uint16_t> first(n);  // each pixel's colour, numbered in the order met
  std::uint32_t last = kEmpty;
  std::uint16_t lastColor = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &picture.rgb[3 * i];
    const std::uint32_t key = std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
    if (key != last) {  // runs of one colour are the common case
      std::uint32_t slot = (key * 2654435761u) >> 23;  // top 9 bits: Fibonacci hashing into 512 slots
      while (keys[slot] != kEmpty && keys[slot] != key) slot = (slot + 1) & (kSlots - 1);
      if (keys[slot] == kEmpty) {
        if (colors.size() == static_cast<std::size_t>(limit)) return std::nullopt;
        keys[slot] = key;
        slotColor[slot] = static_cast<std::uint16_t>(colors.size());
        colors.push_back(key);
        counts.push_back(0);
      }
      last = key;
      lastColor = slotColor[slot];
    }
    first[i] = lastColor;
    ++counts[lastColor];
  }
  // Falling count, ties in the order met (a stable sort keeps it).
  std::vector<std::uint16_t> order(colors.size());
  std::iota(order.begin(), order.end(), std::uint16_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::uint16_t a, std::uint16_t b) { return counts[a] > counts[b]; });
  std::vector<PaletteIndex> indexOf(colors.size());
  IndexedImage out(picture.width, picture.height, colors.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    indexOf[order[k]] = static_cast<PaletteIndex>(k);
    const std::uint32_t c = colors[order[k]];
    out.colormap[k] = Rgb8{static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8),
                           static_cast<std::uint8_t>(c)};
  }
  for (std::size_t i = 0; i < n; ++i) out.pixels[i] = indexOf[first[i]];
  return out;
}

}  // namespace lattice::quantize
