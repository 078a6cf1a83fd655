#include "foundation/rgb_image_source.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice {

RgbImageSource::RgbImageSource(const RgbImage& image) : image_(image) {
  std::size_t expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3;
  if (image.width < 0 || image.height < 0 || image.rgb.size() != expected)
    throw Error(ErrorKind::Internal, fmt::format("RgbImage {}x{} holds {} bytes, expected {}", image.width,
                                                 image.height, image.rgb.size(), expected));
}

void RgbImageSource::row(int y, std::span<Color18> out) {
  if (y < 0 || y >= image_.height || out.size() != static_cast<std::size_t>(image_.width))
    throw Error(ErrorKind::Internal, fmt::format("RgbImageSource: row {} of size {} asked of a {}x{} image", y,
                                                 out.size(), image_.width, image_.height));
  for (int x = 0; x < image_.width; ++x) {
    const std::uint8_t* p = image_.pixel(x, y);
    out[static_cast<std::size_t>(x)] = packColor18(reduce8to6(p[0]), reduce8to6(p[1]), reduce8to6(p[2]));
  }
}

}  // namespace lattice
