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

std::optional<IndexedImage> exactPalette(const IndexedImage& picture, int maxColors) {
  const int limit = std::clamp(maxColors, 1, 256);
  const std::size_t n = static_cast<std::size_t>(picture.width) * static_cast<std::size_t>(picture.height);
  if (n == 0 || picture.pixels.size() < n) return std::nullopt;
  // Per index: its pixels and its first pixel, the order the RGB path meets it.
  std::array<std::uint64_t, 256> indexCount{};
  std::array<std::size_t, 256> indexFirst;
  indexFirst.fill(n);
  for (std::size_t i = 0; i < n; ++i) {
    const PaletteIndex k = picture.pixels[i];
    if (indexCount[k]++ == 0) indexFirst[k] = i;
  }
  // Indices of one colour are one colour; colours numbered in the order met.
  std::vector<std::uint16_t> used;  // indices present, by first pixel
  for (std::size_t k = 0; k < 256; ++k)
    if (indexCount[k] > 0) {
      if (k >= picture.colormap.size()) return std::nullopt;
      used.push_back(static_cast<std::uint16_t>(k));
    }
  std::sort(used.begin(), used.end(), [&](std::uint16_t a, std::uint16_t b) { return indexFirst[a] < indexFirst[b]; });
  std::vector<Rgb8> colors;  // in the order met
  std::vector<std::uint64_t> counts;
  std::array<std::uint16_t, 256> colorOf{};
  for (const std::uint16_t k : used) {
    const Rgb8 c = picture.colormap[k];
    std::size_t j = 0;
    while (j < colors.size() && !(colors[j] == c)) ++j;  // at most 256 x 256 compares, once
    if (j == colors.size()) {
      if (colors.size() == static_cast<std::size_t>(limit)) return std::nullopt;
      colors.push_back(c);
      counts.push_back(0);
    }
    counts[j] += indexCount[k];
    colorOf[k] = static_cast<std::uint16_t>(j);
  }
  // Falling count, ties in the order met, as the RGB path.
  std::vector<std::uint16_t> order(colors.size());
  std::iota(order.begin(), order.end(), std::uint16_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::uint16_t a, std::uint16_t b) { return counts[a] > counts[b]; });
  std::vector<PaletteIndex> rank(colors.size());
  IndexedImage out(picture.width, picture.height, colors.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = static_cast<PaletteIndex>(r);
    out.colormap[r] = colors[order[r]];
  }
  std::array<PaletteIndex, 256> indexOf{};
  for (const std::uint16_t k : used) indexOf[k] = rank[colorOf[k]];
  for (std::size_t i = 0; i < n; ++i) out.pixels[i] = indexOf[picture.pixels[i]];
  return out;
}

}  // namespace lattice::quantize
