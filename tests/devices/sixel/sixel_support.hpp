#pragma once
// Shared by the sixel tests: a frame through the driver into memory, a
// stream through the emulator, and frames of up to 256 colours.
#include <random>
#include <span>
#include <string>
#include <vector>

#include "devices/sixel/sixel_decoder.hpp"
#include "devices/sixel/sixel_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/indexed_image.hpp"

namespace lattice::sixel::test {

inline std::vector<std::uint8_t> driveFrame(const IndexedImage& img, const SixelProfile& profile = {}) {
  MemorySink sink;
  SixelDriver driver(sink, profile);
  driver.begin({img.width, img.height, img.colormap});
  for (int y = 0; y < img.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(&img.pixels[static_cast<std::size_t>(y) * img.width],
                                                static_cast<std::size_t>(img.width)));
  driver.end();
  return sink.data();
}

inline std::string text(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

inline std::vector<std::uint8_t> bytesOf(std::string_view s) { return {s.begin(), s.end()}; }

// A palette of n distinct colours spread over the cube.
inline Palette spreadPalette(int n) {
  Palette p;
  for (int i = 0; i < n; ++i)
    p.push_back({static_cast<std::uint8_t>((i * 97) % 256), static_cast<std::uint8_t>((i * 53 + 40) % 256),
                 static_cast<std::uint8_t>((i * 211 + 7) % 256)});
  return p;
}

// Noise of `colours` colours, in patches of `patch` pixels so runs occur.
inline IndexedImage patchyNoise(int w, int h, int colours, int patch, std::uint32_t seed) {
  IndexedImage img(w, h, static_cast<std::size_t>(colours));
  img.colormap = spreadPalette(colours);
  std::mt19937 rng(seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; x += patch) {
      const auto v = static_cast<PaletteIndex>(rng() % static_cast<std::uint32_t>(colours));
      for (int i = x; i < std::min(w, x + patch); ++i) img.at(i, y) = v;
    }
  return img;
}

}  // namespace lattice::sixel::test
