#pragma once
// Synthetic indexed frames for the 4027 tests: deterministic, so golden
// streams stay stable.
#include <cstdint>
#include <random>
#include <vector>

#include "foundation/indexed_image.hpp"

namespace lattice::testing {

inline Palette eightColours() {
  return {{12, 20, 40}, {240, 240, 230}, {200, 30, 30}, {30, 160, 60},
          {40, 70, 210}, {60, 200, 200}, {190, 60, 180}, {230, 200, 40}};
}

inline IndexedImage noiseImage(int w, int h, int colours, std::uint32_t seed) {
  IndexedImage img(w, h, static_cast<std::size_t>(colours));
  Palette p = eightColours();
  for (std::size_t i = 0; i < img.colormap.size(); ++i) img.colormap[i] = p[i];
  std::mt19937 rng(seed);
  for (auto& px : img.pixels) px = static_cast<PaletteIndex>(rng() % static_cast<std::uint32_t>(colours));
  return img;
}

// Diagonal bands of 8 colours: long runs, many of them linking row to row.
inline IndexedImage gradientImage(int w, int h) {
  IndexedImage img(w, h, 8);
  img.colormap = eightColours();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = static_cast<PaletteIndex>(((x + 2 * y) * 8 / (w + 2 * h)) % 8);
  return img;
}

// Concentric rings with a checkered quadrant: shapes like a rendered scene
// (large areas, curved edges, a fine texture).
inline IndexedImage ringsImage(int w, int h) {
  IndexedImage img(w, h, 8);
  img.colormap = eightColours();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int dx = x - w / 2, dy = y - h / 2;
      int ring = static_cast<int>((dx * dx + dy * dy) / (w * 6 + 1)) % 7;
      if (x < w / 4 && y < h / 4 && ((x / 4 + y / 4) % 2 == 0)) ring = 7;
      img.at(x, y) = static_cast<PaletteIndex>(ring);
    }
  return img;
}

inline IndexedImage singleColourImage(int w, int h, Rgb8 colour) {
  IndexedImage img(w, h, 1);
  img.colormap[0] = colour;
  return img;
}

}  // namespace lattice::testing
