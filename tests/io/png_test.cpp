#include <catch2/catch.hpp>

#include <filesystem>
#include <unistd.h>

#include "foundation/atomic_file.hpp"
#include "io/png.hpp"
#include "foundation/error.hpp"

using namespace lattice;
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
