#pragma once
// A whole indexed frame: what an emulator decodes a stream into, and what the
// pipeline hands a driver row by row. Golden tests compare two of these after
// resolving indices through their colour maps (a driver may renumber entries).
#include <cstdint>
#include <span>
#include <vector>

#include "foundation/scanline.hpp"

namespace lattice {

struct IndexedImage {
  int width = 0;
  int height = 0;
  std::vector<PaletteIndex> pixels;  // row-major, width*height
  Palette colormap;                  // colour of each index (at least max index + 1 entries)

  IndexedImage() = default;
  IndexedImage(int w, int h, std::size_t colors = 256)
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0),
        colormap(colors) {}

  PaletteIndex& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
  PaletteIndex at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
  Rgb8 colorAt(int x, int y) const { return colormap.at(at(x, y)); }
  // Resolve every pixel through the colour map: 3 bytes a pixel, row-major.
  std::vector<std::uint8_t> toRgb() const;
};

// An IndexedSink that keeps the whole frame: for tests, PNG output and the
// quantize command.
class IndexedImageSink final : public IndexedSink {
 public:
  explicit IndexedImageSink(int maxColors = 256) : maxColors_(maxColors) {}
  int maxColors() const override { return maxColors_; }
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  void end() override {}
  const IndexedImage& image() const { return image_; }

 private:
  int maxColors_;
  IndexedImage image_;
};

}  // namespace lattice
