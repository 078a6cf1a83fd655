#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <png.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "foundation/system/atomic_file.hpp"
#include "io/image_metrics.hpp"
#include "io/png.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::io;
namespace fs = std::filesystem;

namespace {
fs::path tempPath(const std::string& name) {
  return fs::temp_directory_path() / ("lattice-png-" + std::to_string(::getpid()) + "-" + name);
}
}  // namespace

TEST_CASE("RGB PNG round-trips exactly") {
  RgbImage img(37, 11);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      auto* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 23);
      p[2] = static_cast<std::uint8_t>(x ^ y);
    }
  fs::path path = tempPath("rgb.png");
  writePng(path, img);
  RgbImage back = readPng(path);
  CHECK(back.width == 37);
  CHECK(back.height == 11);
  CHECK(back.rgb == img.rgb);
  fs::remove(path);
}

TEST_CASE("indexed PNG resolves through its colour map") {
  IndexedImage img(5, 3, 3);
  img.colormap = {{0, 0, 0}, {255, 0, 0}, {10, 20, 30}};
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) img.at(x, y) = static_cast<PaletteIndex>((x + y) % 3);
  fs::path path = tempPath("indexed.png");
  writePng(path, img);
  RgbImage back = readPng(path);
  CHECK(back.rgb == img.toRgb());
  fs::remove(path);
}

TEST_CASE("a file that is not a PNG is refused with its name") {
  fs::path path = tempPath("garbage.png");
  writeFileAtomically(path, std::vector<std::uint8_t>{'n', 'o', 't', ' ', 'p', 'n', 'g'});
  try {
    readPng(path);
    FAIL("garbage must not decode");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK(std::string(e.what()).find(path.filename().string()) != std::string::npos);
  }
  fs::remove(path);
}

TEST_CASE("a truncated PNG is refused, not half-read") {
  RgbImage img(64, 64);
  for (auto& b : img.rgb) b = static_cast<std::uint8_t>(&b - img.rgb.data());
  fs::path path = tempPath("trunc.png");
  writePng(path, img);
  auto bytes = readWholeFile(path);
  bytes.resize(bytes.size() / 2);
  writeFileAtomically(path, bytes);
  CHECK_THROWS_AS(readPng(path), Error);
  fs::remove(path);
}

namespace {

void appendChunk(std::vector<std::uint8_t>& png, const char* type, const std::vector<std::uint8_t>& data) {
  auto be32 = [&](std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<std::uint8_t>(v >> s));
  };
  be32(static_cast<std::uint32_t>(data.size()));
  const std::size_t start = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  be32(static_cast<std::uint32_t>(crc32(0, png.data() + start, static_cast<uInt>(png.size() - start))));
}

// A PNG whose IHDR claims width x height (8-bit RGB) followed by a tiny IDAT:
// 66 bytes, whatever size it claims.
std::vector<std::uint8_t> liarPng(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> ihdr;
  for (std::uint32_t v : {width, height})
    for (int s = 24; s >= 0; s -= 8) ihdr.push_back(static_cast<std::uint8_t>(v >> s));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
  appendChunk(png, "IHDR", ihdr);
  appendChunk(png, "IDAT", {0x78, 0x9c, 0x63, 0x00, 0x00, 0x00, 0x01, 0x00, 0x01});
  appendChunk(png, "IEND", {});
  return png;
}

}  // namespace

TEST_CASE("a PNG header claiming a huge picture is refused before any pixel memory") {
  const lattice::testing::TempDir scratch("png-liar");
  for (const auto& [w, h] : {std::pair<std::uint32_t, std::uint32_t>{65535, 65535}, {20000, 20000}, {16384, 8193}}) {
    const auto bytes = liarPng(w, h);
    const std::string path = scratch / "liar.png";
    writeFileAtomically(path, bytes);
    INFO(w << "x" << h << ", " << bytes.size() << " bytes");
    try {
      readPng(path);
      FAIL("a lying header was accepted");
    } catch (const Error& e) {
      const std::string message = e.what();
      CHECK(e.kind() == ErrorKind::Input);
      CHECK(message.find(path) != std::string::npos);
      CHECK(message.find(fmt::format("{}x{}", w, h)) != std::string::npos);
      CHECK(message.find(std::to_string(kMaxPngPixels)) != std::string::npos);
    }
    CHECK_THROWS_AS(readPngBytes(bytes, "bytes"), Error);
  }
  // The CLI's side: exit 3 naming the file, also under a memory cap that a
  // 12.9 GB allocation would break.
#ifdef LATTICE_SANITIZED
  WARN("the CLI run under `ulimit -v` is skipped under the sanitizers: ASan reserves terabytes of address space "
       "for its shadow memory, so no sanitized binary starts under the cap (the g++ build runs it)");
  return;
#endif
  const std::string path = scratch / "liar.png";
  writeFileAtomically(path, liarPng(65535, 65535));
  const int status = std::system(fmt::format("ulimit -v 400000; exec '{}' quantize '{}' -o '{}' 2>/dev/null",
                                             lattice::testing::latticeBinary().string(), path,
                                             scratch / "out.png")
                                     .c_str());
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 3);
}

TEST_CASE("PNG samples are read as written: a gAMA chunk changes nothing") {
  // A real PNG with gAMA 1.0 (as POV-Ray writes), written by libpng's own
  // writer; readPng must return the stored samples, not sRGB conversions.
  const lattice::testing::TempDir scratch("png-gama");
  RgbImage img(16, 4);
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = static_cast<std::uint8_t>(i * 5 + 1);
  const std::string gamaPath = scratch / "gama.png";
  {
    std::FILE* out = std::fopen(gamaPath.c_str(), "wb");
    REQUIRE(out != nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    REQUIRE(setjmp(png_jmpbuf(png)) == 0);
    png_init_io(png, out);
    png_set_IHDR(png, info, 16, 4, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_gAMA(png, info, 1.0);
    png_write_info(png, info);
    for (int y = 0; y < 4; ++y) png_write_row(png, img.pixel(0, y));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(out);
  }
  const auto bytes = readWholeFile(gamaPath);
  const std::string text(bytes.begin(), bytes.end());
  REQUIRE(text.find("gAMA") != std::string::npos);
  const RgbImage back = readPng(gamaPath);
  CHECK(back.rgb == img.rgb);
  // `lattice diff` of that file against the same samples without gAMA.
  const std::string plainPath = scratch / "plain.png";
  writePng(plainPath, img);
  const ImageMetrics m = compareRgbFiles(gamaPath, plainPath, 2);
  CHECK(m.differingPixels == 0);
  CHECK(m.maxChannelError == 0);
}
