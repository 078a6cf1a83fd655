// The banded PNG encoder (io/png_encoder.hpp): every setting decodes to the
// same pixels through libpng (a real decoder, which checks each chunk's CRC
// and the zlib stream's Adler-32), pictures taller than one band are cut into
// several IDAT chunks, and the bytes do not depend on the thread count.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "io/png.hpp"
#include "io/png_encoder.hpp"

using namespace lattice;
using namespace lattice::io;

namespace {

// Smooth gradients with noise and a flat block: what filters and matches
// meet in a rendered picture. 400 x 700 RGB is 1200 bytes a row, about
// 218 rows a band: four bands, the last one short.
RgbImage testPicture(int width = 400, int height = 700) {
  RgbImage img(width, height);
  std::mt19937 random(7);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      const bool flat = x > 100 && x < 200 && y > 300 && y < 500;
      p[0] = flat ? 40 : static_cast<std::uint8_t>(x / 2 + random() % 4);
      p[1] = flat ? 40 : static_cast<std::uint8_t>(y / 3);
      p[2] = flat ? 90 : static_cast<std::uint8_t>((x + y) / 5 + random() % 2);
    }
  return img;
}

// The chunk types of a PNG file in order.
std::vector<std::string> chunkTypes(const std::vector<std::uint8_t>& file) {
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 8 <= file.size();) {
    const std::size_t length = std::size_t(file[at]) << 24 | std::size_t(file[at + 1]) << 16 |
                               std::size_t(file[at + 2]) << 8 | file[at + 3];
    types.emplace_back(reinterpret_cast<const char*>(&file[at + 4]), 4);
    at += 12 + length;
  }
  return types;
}

}  // namespace

TEST_CASE("PNG encoder: every filter, level and strategy decodes to the same pixels") {
  const RgbImage img = testPicture();
  for (PngFilter filter : {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth})
    for (int level : {0, 1, 6, 9})
      for (bool runLength : {false, true}) {
        INFO("filter " << int(filter) << ", level " << level << ", Z_RLE " << runLength);
        const auto file = encodePng({img.width, img.height, img.rgb, {}}, {level, runLength, filter, 2});
        const RgbImage back = readPngBytes(file, "encoded");
        REQUIRE(back.width == img.width);
        REQUIRE(back.height == img.height);
        CHECK(back.rgb == img.rgb);
      }
}

TEST_CASE("PNG encoder: a tall picture goes out in bands, one IDAT each, the same bytes on any thread count") {
  const RgbImage img = testPicture();
  PngEncoding encoding;  // what io/png.cpp writes with
  encoding.threads = 1;
  const auto one = encodePng({img.width, img.height, img.rgb, {}}, encoding);
  CHECK(chunkTypes(one) == std::vector<std::string>{"IHDR", "sRGB", "IDAT", "IDAT", "IDAT", "IDAT", "IEND"});
  CHECK(readPngBytes(one, "one thread").rgb == img.rgb);
  for (unsigned threads : {2u, 3u, 8u}) {
    INFO(threads << " threads");
    encoding.threads = threads;
    CHECK(encodePng({img.width, img.height, img.rgb, {}}, encoding) == one);
  }
  // A picture of one band, and one of a single row narrower than a pixel's filter reach.
  const RgbImage small = testPicture(5, 1);
  CHECK(readPngBytes(encodePng({5, 1, small.rgb, {}}, {}), "small").rgb == small.rgb);
}

TEST_CASE("PNG encoder: a palette picture keeps its indices and colours") {
  std::vector<Rgb8> palette;
  for (int i = 0; i < 256; ++i) palette.push_back({std::uint8_t(i), std::uint8_t(255 - i), std::uint8_t(i * 7)});
  const int width = 1000, height = 700;  // several bands at one byte a pixel
  std::vector<std::uint8_t> indices(std::size_t(width) * height);
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint8_t>((i / 3 + i / 1711) % 256);
  const auto file = encodePng({width, height, indices, palette}, {1, false, PngFilter::None, 2});
  CHECK(chunkTypes(file).at(2) == "PLTE");
  const RgbImage back = readPngBytes(file, "indexed");
  REQUIRE(back.rgb.size() == indices.size() * 3);
  for (std::size_t i = 0; i < indices.size(); i += 997) {
    INFO("pixel " << i);
    CHECK(back.rgb[3 * i] == palette[indices[i]].r);
    CHECK(back.rgb[3 * i + 1] == palette[indices[i]].g);
    CHECK(back.rgb[3 * i + 2] == palette[indices[i]].b);
  }
}
