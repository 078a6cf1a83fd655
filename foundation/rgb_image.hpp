#pragma once
// A truecolour picture in memory: 8 bits a channel, RGB, row-major, top row
// first. What the renderer's truecolour output, PNG files and the image
// metrics share; it knows no file format.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "foundation/indexed_image.hpp"

namespace lattice {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 * width * height

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3]; }
};

// Every pixel resolved through the image's colour map.
RgbImage toRgbImage(const IndexedImage& image);

}  // namespace lattice
