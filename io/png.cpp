#include "io/png.hpp"

#include <fmt/format.h>
#include <png.h>

#include <cstring>

#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"

namespace lattice::io {
namespace {

void encodeAndWrite(const std::filesystem::path& path, png_image& image, const void* pixels,
                    const void* colormap, AtomicFile::Landing landing) {
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&image, nullptr, &size, 0, pixels, 0, colormap))
    throw Error(ErrorKind::Output, fmt::format("{}: PNG encoding failed: {}", path.string(), image.message));
  std::vector<std::uint8_t> buffer(size);
  if (!png_image_write_to_memory(&image, buffer.data(), &size, 0, pixels, 0, colormap))
    throw Error(ErrorKind::Output, fmt::format("{}: PNG encoding failed: {}", path.string(), image.message));
  buffer.resize(size);
  writeFileAtomically(path, buffer, landing);
}

}  // namespace

void writePng(const std::filesystem::path& path, const RgbImage& img, AtomicFile::Landing landing) {
  if (img.width <= 0 || img.height <= 0)
    throw Error(ErrorKind::Output, fmt::format("{}: cannot write an empty image", path.string()));
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(img.width);
  image.height = static_cast<png_uint_32>(img.height);
  image.format = PNG_FORMAT_RGB;
  encodeAndWrite(path, image, img.rgb.data(), nullptr, landing);
}

void writePng(const std::filesystem::path& path, const IndexedImage& img, AtomicFile::Landing landing) {
  if (img.width <= 0 || img.height <= 0)
    throw Error(ErrorKind::Output, fmt::format("{}: cannot write an empty image", path.string()));
  if (img.colormap.empty() || img.colormap.size() > 256) {
    writePng(path, toRgbImage(img), landing);
    return;
  }
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(img.width);
  image.height = static_cast<png_uint_32>(img.height);
  image.format = PNG_FORMAT_RGB_COLORMAP;
  image.colormap_entries = static_cast<png_uint_32>(img.colormap.size());
  std::vector<std::uint8_t> cmap;
  for (const Rgb8& c : img.colormap) cmap.insert(cmap.end(), {c.r, c.g, c.b});
  // Indices beyond the map would make libpng fail; clamp them to entry 0 (a
  // decoder's framebuffer may hold an index the stream never defined).
  std::vector<std::uint8_t> pixels(img.pixels.begin(), img.pixels.end());
  for (auto& p : pixels)
    if (p >= img.colormap.size()) p = 0;
  encodeAndWrite(path, image, pixels.data(), cmap.data(), landing);
}

}  // namespace lattice::io
