#pragma once
// Synthetic indexed pictures and the driver -> bytes -> emulator plumbing the
// tek4125 tests share. The renderer is not used: these tests must isolate
// the device code.
#include <cstdint>
#include <random>
#include <vector>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/indexed_image.hpp"

namespace lattice::tek4125::test {

// A palette of n distinct colours spread over the RGB cube.
inline Palette spreadPalette(int n) {
  Palette p(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    p[static_cast<std::size_t>(i)] = Rgb8{static_cast<std::uint8_t>(i * 255 / std::max(1, n - 1)),
                                          static_cast<std::uint8_t>((i * 97) % 256),
                                          static_cast<std::uint8_t>(255 - (i * 53) % 256)};
  return p;
}

inline IndexedImage gradient(int w, int h, int colors) {
  IndexedImage img(w, h, 0);
  img.colormap = spreadPalette(colors);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = static_cast<PaletteIndex>((x + y) * colors / (w + h));
  return img;
}

inline IndexedImage noise(int w, int h, int colors, unsigned seed) {
  IndexedImage img(w, h, 0);
  img.colormap = spreadPalette(colors);
  std::mt19937 rng(seed);
  for (auto& p : img.pixels) p = static_cast<PaletteIndex>(rng() % static_cast<unsigned>(colors));
  return img;
}

inline IndexedImage flat(int w, int h, int colors, PaletteIndex index) {
  IndexedImage img(w, h, 0);
  img.colormap = spreadPalette(colors);
  std::fill(img.pixels.begin(), img.pixels.end(), index);
  return img;
}

// A stand-in for a rendered scene: background (index 0), a shaded disc, a
// flat floor band and a noisy (dithered-looking) patch.
inline IndexedImage scene(int w, int h, int colors) {
  IndexedImage img(w, h, 0);
  img.colormap = spreadPalette(colors);
  std::mt19937 rng(7);
  const double cx = w * 0.45, cy = h * 0.45, r = std::min(w, h) * 0.35;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double dx = x - cx, dy = y - cy, d = std::sqrt(dx * dx + dy * dy);
      PaletteIndex v = 0;
      if (d < r) v = static_cast<PaletteIndex>(1 + static_cast<int>((1.0 - d / r) * (colors - 3)));
      else if (y > h * 0.8) v = static_cast<PaletteIndex>(colors - 1);
      if (x > w * 0.75 && y < h * 0.3 && rng() % 2) v = static_cast<PaletteIndex>(rng() % static_cast<unsigned>(colors));
      img.at(x, y) = v;
    }
  return img;
}

inline void sendImage(IndexedSink& sink, const IndexedImage& img) {
  sink.begin(FrameInfo{img.width, img.height, img.colormap});
  for (int y = 0; y < img.height; ++y)
    sink.row(y, std::span<const PaletteIndex>(img.pixels).subspan(static_cast<std::size_t>(y * img.width),
                                                                  static_cast<std::size_t>(img.width)));
  sink.end();
}

inline std::vector<std::uint8_t> encode(const IndexedImage& img, const Tek4125Profile& profile,
                                        Tek4125DriverOptions options = {}, Tek4125StreamStats* stats = nullptr) {
  MemorySink sink;
  Tek4125Driver driver(sink, profile, options);
  sendImage(driver, img);
  if (stats) *stats = driver.stats();
  return sink.data();
}

// The picture's rectangle cut out of the emulator's screen, with the screen's colour map.
inline IndexedImage cutPicture(const IndexedImage& screen, const Tek4125Profile& profile, int w, int h) {
  const Tek4125Placement place = placePicture(profile, w, h);
  IndexedImage out(w, h, 0);
  out.colormap = screen.colormap;
  const int top = profile.height - 1 - (place.bottom + h - 1);  // screen row of picture row 0
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.at(x, y) = screen.at(place.left + x, top + y);
  return out;
}

}  // namespace lattice::tek4125::test
