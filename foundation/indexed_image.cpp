#include "foundation/indexed_image.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "foundation/error.hpp"

namespace lattice {

std::vector<std::uint8_t> IndexedImage::toRgb() const {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(pixels.size() * 3);
  for (PaletteIndex i : pixels) {
    Rgb8 c = i < colormap.size() ? colormap[i] : Rgb8{};
    rgb.push_back(c.r);
    rgb.push_back(c.g);
    rgb.push_back(c.b);
  }
  return rgb;
}

void IndexedImageSink::begin(const FrameInfo& frame) {
  image_ = IndexedImage(frame.width, frame.height, 0);
  image_.colormap = frame.palette;
}

void IndexedImageSink::row(int y, std::span<const PaletteIndex> indices) {
  if (y < 0 || y >= image_.height || indices.size() != static_cast<std::size_t>(image_.width))
    throw Error(ErrorKind::Internal, fmt::format("IndexedImageSink: row {} of {} pixels for a {}x{} frame", y,
                                                 indices.size(), image_.width, image_.height));
  std::copy(indices.begin(), indices.end(),
            image_.pixels.begin() + static_cast<std::ptrdiff_t>(y) * image_.width);
}

}  // namespace lattice
