// The figures `lattice diff` prints come from io/image_metrics; these tests pin
// them on images small enough to work out by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "foundation/system/atomic_file.hpp"
#include "io/image_metrics.hpp"
#include "io/png.hpp"
#include "tests/support/temp_dir.hpp"
#include "foundation/error.hpp"

namespace {

lattice::RgbImage gradient(int w, int h) {
  lattice::RgbImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 20);
      p[1] = static_cast<std::uint8_t>(y * 20);
      p[2] = 100;
    }
  return image;
}


}  // namespace

TEST_CASE("identical images have no error and infinite PSNR", "[diff]") {
  const auto a = gradient(10, 7);
  const lattice::io::ImageMetrics m = lattice::io::compareRgb(a, a, 4);
  CHECK(m.rms == 0.0);
  CHECK(std::isinf(m.psnr));
  CHECK(m.maxChannelError == 0);
  CHECK(m.differingPixels == 0);
  CHECK(m.worstBlockMean == 0.0);
  CHECK(m.meanBlockMean == 0.0);
}

TEST_CASE("one changed channel gives the hand-computed figures", "[diff]") {
  const auto a = gradient(10, 10);
  auto b = a;
  b.pixel(9, 9)[0] = static_cast<std::uint8_t>(b.pixel(9, 9)[0] - 30);
  const lattice::io::ImageMetrics m = lattice::io::compareRgb(a, b, 4);
  // 300 samples, one off by 30: MSE = 900 / 300 = 3.
  CHECK(m.rms == Approx(std::sqrt(3.0)));
  CHECK(m.psnr == Approx(20.0 * std::log10(255.0 / std::sqrt(3.0))));
  CHECK(m.maxChannelError == 30);
  CHECK(m.differingPixels == 1);
  // The pixel sits in the 2x2 corner block (8, 8): 30 over 4 pixels x 3 channels.
  CHECK(m.worstBlockX == 8);
  CHECK(m.worstBlockY == 8);
  CHECK(m.worstBlockMean == Approx(2.5));
  CHECK(m.meanBlockMean == Approx(2.5 / 9.0));  // 3 x 3 blocks
}

TEST_CASE("the worst block is found where the error is concentrated", "[diff]") {
  const auto a = gradient(16, 16);
  auto b = a;
  // A spread-out error: one channel off by 2 in every pixel...
  for (std::size_t i = 0; i < b.rgb.size(); i += 3) b.rgb[i] = static_cast<std::uint8_t>(b.rgb[i] + 2);
  // ...and a local one in the block at (8, 0).
  for (int y = 0; y < 8; ++y)
    for (int x = 8; x < 16; ++x) b.pixel(x, y)[2] = 200;  // was 100
  const lattice::io::ImageMetrics m = lattice::io::compareRgb(a, b, 8);
  CHECK(m.worstBlockX == 8);
  CHECK(m.worstBlockY == 0);
  CHECK(m.worstBlockMean == Approx((2.0 + 100.0) / 3.0));
  CHECK(m.meanBlockMean == Approx((3 * 2.0 / 3.0 + (2.0 + 100.0) / 3.0) / 4.0));
  CHECK(m.differingPixels == 256);
  CHECK(m.maxChannelError == 100);
}

TEST_CASE("images of different sizes or a bad block size are refused", "[diff]") {
  const auto a = gradient(10, 10);
  const auto b = gradient(10, 9);
  CHECK_THROWS_AS(lattice::io::compareRgb(a, b), lattice::Error);
  try {
    lattice::io::compareRgb(a, b);
  } catch (const lattice::Error& e) {
    CHECK(e.kind() == lattice::ErrorKind::Input);
    CHECK_THAT(e.what(), Catch::Contains("10x10") && Catch::Contains("10x9"));
  }
  CHECK_THROWS_AS(lattice::io::compareRgb(a, a, 0), lattice::Error);
  CHECK_THROWS_AS(lattice::io::amplifiedDifference(a, b, 8.0), lattice::Error);
  CHECK_THROWS_AS(lattice::io::amplifiedDifference(a, a, 0.0), lattice::Error);
}

TEST_CASE("the difference image amplifies and clamps", "[diff]") {
  auto a = gradient(4, 4);
  auto b = a;
  b.pixel(1, 1)[0] = static_cast<std::uint8_t>(a.pixel(1, 1)[0] + 3);
  b.pixel(2, 2)[2] = 0;  // off by 100
  const lattice::RgbImage d = lattice::io::amplifiedDifference(a, b, 8.0);
  REQUIRE(d.width == 4);
  REQUIRE(d.height == 4);
  CHECK(int{d.pixel(1, 1)[0]} == 24);
  CHECK(int{d.pixel(2, 2)[2]} == 255);
  CHECK(int{d.pixel(0, 0)[0]} == 0);
  CHECK(int{d.pixel(2, 2)[0]} == 0);
}

TEST_CASE("comparing files names the file that cannot be read", "[diff]") {
  const lattice::testing::TempDir dir("diff-test");
  const auto good = dir / "good.png";
  const auto other = dir / "other.png";
  const auto bad = dir / "bad.png";
  const auto small = dir / "small.png";
  auto a = gradient(6, 6);
  auto b = a;
  b.pixel(0, 0)[1] = 255;
  lattice::io::writePng(good, a);
  lattice::io::writePng(other, b);
  lattice::io::writePng(small, gradient(5, 6));
  const std::string junk = "not a png at all";
  lattice::writeFileAtomically(bad, std::span(reinterpret_cast<const std::uint8_t*>(junk.data()), junk.size()));

  const lattice::io::ImageMetrics m = lattice::io::compareRgbFiles(good, other, 8);
  CHECK(m.differingPixels == 1);
  CHECK(m.maxChannelError == 255);

  try {
    lattice::io::compareRgbFiles(good, bad);
    FAIL("a file that is not a PNG was accepted");
  } catch (const lattice::Error& e) {
    CHECK_THAT(e.what(), Catch::Contains("bad.png"));
  }
  try {
    lattice::io::compareRgbFiles(good, small);
    FAIL("images of different sizes were compared");
  } catch (const lattice::Error& e) {
    CHECK_THAT(e.what(), Catch::Contains("small.png") && Catch::Contains("good.png"));
  }
}
