// Writing PNG files: a picture handed to the banded encoder, the file
// written atomically.
#include "io/png.hpp"

#include <fmt/format.h>

#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "io/png_encoder.hpp"

namespace lattice::io {
namespace {

void writeEncoded(const std::filesystem::path& path, const PngPixels& pixels, const PngEncoding& encoding) {
  AtomicFile file(path);
  encodePng(pixels, encoding, file);
  file.close();
}

}  // namespace

void writePng(const std::filesystem::path& path, const RgbImage& img, unsigned threads) {
  if (img.width <= 0 || img.height <= 0)
    throw Error(ErrorKind::Output, fmt::format("{}: cannot write an empty image", path.string()));
  PngEncoding encoding;
  encoding.threads = threads;
  writeEncoded(path, {img.width, img.height, img.rgb, {}}, encoding);
}

void writePng(const std::filesystem::path& path, const IndexedImage& img, unsigned threads) {
  if (img.width <= 0 || img.height <= 0)
    throw Error(ErrorKind::Output, fmt::format("{}: cannot write an empty image", path.string()));
  if (img.colormap.empty() || img.colormap.size() > 256) {
    writePng(path, toRgbImage(img), threads);
    return;
  }
  // Indices beyond the map would make a PNG no decoder accepts; clamp them to
  // entry 0 (a decoder's framebuffer may hold an index the stream never defined).
  std::vector<std::uint8_t> pixels(img.pixels.begin(), img.pixels.end());
  for (auto& p : pixels)
    if (p >= img.colormap.size()) p = 0;
  PngEncoding encoding;  // no filter, as W3C PNG 12.8 advises for palette pictures
  encoding.threads = threads;
  writeEncoded(path, {img.width, img.height, pixels, img.colormap}, encoding);
}

}  // namespace lattice::io
