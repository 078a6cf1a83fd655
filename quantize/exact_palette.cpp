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

// The colours' positions by falling count, ties in the order met (a stable
// sort keeps it): the palette order both paths give.
std::vector<std::uint16_t> byFallingCount(const std::vector<std::uint64_t>& counts) {
  std::vector<std::uint16_t> order(counts.size());
  std::iota(order.begin(), order.end(), std::uint16_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::uint16_t a, std::uint16_t b) { return counts[a] > counts[b]; });
  return order;
}

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
  const std::vector<std::uint16_t> order = byFallingCount(counts);
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
  // Per index: its pixels, in four tallies by position so that a run of one
  // index does not make each increment wait for the one before it.
  std::array<std::array<std::uint32_t, 256>, 4> tally{};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (std::size_t t = 0; t < 4; ++t) ++tally[t][picture.pixels[i + t]];
  for (; i < n; ++i) ++tally[0][picture.pixels[i]];
  std::array<std::uint64_t, 256> indexCount{};
  std::vector<std::uint16_t> used;  // indices present
  for (std::size_t k = 0; k < 256; ++k) {
    indexCount[k] = std::uint64_t(tally[0][k]) + tally[1][k] + tally[2][k] + tally[3][k];
    if (indexCount[k] > 0) {
      if (k >= picture.colormap.size()) return std::nullopt;
      used.push_back(static_cast<std::uint16_t>(k));
    }
  }
  // Each index's first pixel, the order the RGB path meets it: a scan that
  // stops once every index present is found (usually within a few rows).
  std::array<std::size_t, 256> indexFirst;
  indexFirst.fill(n);
  for (std::size_t j = 0, found = 0; j < n && found < used.size(); ++j) {
    std::size_t& first = indexFirst[picture.pixels[j]];
    if (first == n) first = j, ++found;
  }
  // Indices of one colour are one colour; colours numbered in the order met.
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
  const std::vector<std::uint16_t> order = byFallingCount(counts);
  std::vector<PaletteIndex> rank(colors.size());
  IndexedImage out(picture.width, picture.height, colors.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = static_cast<PaletteIndex>(r);
    out.colormap[r] = colors[order[r]];
  }
  std::array<PaletteIndex, 256> indexOf{};
  for (const std::uint16_t k : used) indexOf[k] = rank[colorOf[k]];
  bool same = true;  // a stream we wrote: its registers are already ranked so
  for (const std::uint16_t k : used) same = same && indexOf[k] == k;
  if (same) std::copy_n(picture.pixels.begin(), n, out.pixels.begin());
  else
    for (std::size_t j = 0; j < n; ++j) out.pixels[j] = indexOf[picture.pixels[j]];
  return out;
}

}  // namespace lattice::quantize
