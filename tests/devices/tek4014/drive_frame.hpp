#pragma once
// Feeds an indexed frame through a Tek4014Driver row by row, and decodes a
// stream with the emulator: what the 4014 tests share.
#include <span>
#include <vector>

#include "devices/tek4014/tek4014_decoder.hpp"
#include "devices/tek4014/tek4014_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/indexed_image.hpp"

namespace lattice::tek4014::test {

inline std::vector<std::uint8_t> driveFrame(const IndexedImage& img, const Tek4014Profile& profile,
                                            Tek4014Stats* stats = nullptr) {
  MemorySink sink;
  Tek4014Driver driver(sink, profile);
  driver.begin({img.width, img.height, img.colormap});
  for (int y = 0; y < img.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(&img.pixels[static_cast<std::size_t>(y) * img.width],
                                                static_cast<std::size_t>(img.width)));
  driver.end();
  if (stats != nullptr) *stats = driver.stats();
  return sink.data();
}

inline Tek4014Decoder decode(std::span<const std::uint8_t> stream, const Tek4014Profile& profile) {
  Tek4014Decoder decoder(profile);
  decoder.feed(stream);
  decoder.finish();
  return decoder;
}

// The dots the driver's dither makes of a frame, top row first (1 lit).
inline std::vector<std::uint8_t> ditheredDots(const IndexedImage& img, Tek4014Dither method) {
  RowDither dither(method, img.width, img.colormap);
  std::vector<std::uint8_t> dots(img.pixels.size());
  for (int y = 0; y < img.height; ++y) {
    const auto at = static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width);
    dither.row(y, std::span<const PaletteIndex>(&img.pixels[at], static_cast<std::size_t>(img.width)),
               std::span<std::uint8_t>(&dots[at], static_cast<std::size_t>(img.width)));
  }
  return dots;
}

}  // namespace lattice::tek4014::test
