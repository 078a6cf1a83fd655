#pragma once
// PNG files through libpng's simplified API. Writes are atomic (see
// atomic_file.hpp); reads refuse anything libpng cannot decode with an error
// naming the file.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "pipeline/indexed_image.hpp"

namespace lattice {

// 8 bits a channel, RGB, row-major, top row first.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 * width * height

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3]; }
};

void writePng(const std::filesystem::path& path, const RgbImage& image);
// Writes a palette PNG (colour type 3) when the map has <= 256 entries.
void writePng(const std::filesystem::path& path, const IndexedImage& image);
RgbImage readPng(const std::filesystem::path& path);  // any PNG, converted to 8-bit RGB
RgbImage toRgbImage(const IndexedImage& image);

}  // namespace lattice
