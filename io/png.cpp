// Writing PNG files: a picture handed to the banded encoder, the file
// written atomically.
#include "io/png.hpp"

#include <fmt/format.h>

#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "io/png_encoder.hpp"

namespace lattice::io {
namespace {

void writeEncoded(const std::filesystem::path& path, const PngPixels& pixels, const PngEncoding& encoding,
                  AtomicFile::Landing landing) {
  AtomicFile file(path, landing);
  encodePng(pixels, encoding, file);
  file.close();
}

}  // namespace

void writePng(const std::filesystem::path& path, const RgbImage& img, unsigned threads, AtomicFile::Landing landing) {
  if (img.width <= 0 || img.height <= 0)
    throw Error(ErrorKind::Output, fmt::format("{}: cannot write an empty image", path.string()));
  PngEncoding encoding;
  encoding.threads = threads;
  writeEncoded(path, {img.width, img.height, img.rgb, {}}, encoding, landing);
}

void writePng(const std::filesystem::path& path, const IndexedImage& img, unsigned threads,
              AtomicFile::Landing landing) {
  if (img.width <= 0 || img.height <= 0)
    throw Error(ErrorKind::Output, fmt::format("{}: cannot write an empty image", path.string()));
  if (img.colormap.empty() || img.colormap.size() > 256) {
    writePng(path, toRgbImage(img), threads, landing);
    return;
  }
  // Indices beyond the map would make a PNG no decoder accepts; clamp them to
  // entry 0 (a decoder's framebuffer may hold an index the stream never defined).
  std::vector<std::uint8_t> pixels(img.pixels.begin(), img.pixels.end());
  for (auto& p : pixels)
    if (p >= img.colormap.size()) p = 0;
  PngEncoding encoding;  // no filter, as W3C PNG 12.8 advises for palette pictures
  encoding.threads = threads;
  writeEncoded(path, {img.width, img.height, pixels, img.colormap}, encoding, landing);
}

}  // namespace lattice::io
