#pragma once
// Feeds an indexed frame through a Tek4027Driver row by row: the one way the
// 4027 tests hand a picture to the driver.
#include <span>
#include <string>

#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/indexed_image.hpp"

namespace lattice::tek4027::test {

inline void feedFrame(Tek4027Driver& driver, const IndexedImage& img) {
  driver.begin({img.width, img.height, img.colormap});
  for (int y = 0; y < img.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(&img.pixels[static_cast<std::size_t>(y) * img.width],
                                                static_cast<std::size_t>(img.width)));
  driver.end();
}

// The whole stream as text, from a fresh driver over memory.
inline std::string driveFrame(const IndexedImage& img, const Tek4027Profile& profile,
                              Tek4027Strategy strategy = Tek4027Strategy::Shortest) {
  MemorySink sink;
  Tek4027Driver driver(sink, profile, strategy);
  feedFrame(driver, img);
  return {sink.data().begin(), sink.data().end()};
}

}  // namespace lattice::tek4027::test
