#pragma once
// PNG files through libpng's simplified API. Writes are atomic (see
// atomic_file.hpp); reads refuse anything libpng cannot decode with an error
// naming the file.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "foundation/indexed_image.hpp"
#include "foundation/rgb_image.hpp"

namespace lattice {

void writePng(const std::filesystem::path& path, const RgbImage& image);
// Writes a palette PNG (colour type 3) when the map has <= 256 entries.
void writePng(const std::filesystem::path& path, const IndexedImage& image);
RgbImage readPng(const std::filesystem::path& path);  // any PNG, converted to 8-bit RGB

}  // namespace lattice
