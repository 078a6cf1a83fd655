#include <catch2/catch.hpp>

#include <vector>

#include "foundation/rgb_image_source.hpp"
#include "foundation/error.hpp"

using namespace lattice;

TEST_CASE("rgb image source rounds each channel to 6 bits") {
  RgbImage image(2, 2);
  std::uint8_t* p = image.pixel(1, 0);
  p[0] = 255;
  p[1] = 130;
  p[2] = 2;
  std::uint8_t* q = image.pixel(0, 1);
  q[0] = 3;
  q[1] = 1;
  q[2] = 128;
  RgbImageSource source(image);
  CHECK(source.width() == 2);
  CHECK(source.height() == 2);
  std::vector<Color18> row(2);
  source.row(0, row);
  CHECK(row[0] == packColor18(0, 0, 0));
  CHECK(row[1] == packColor18(63, 32, 0));  // 130 * 63 / 255 = 32.1; 2 -> 0.49 rounds down
  source.row(1, row);
  CHECK(row[0] == packColor18(1, 0, 32));  // 3 -> 0.74 rounds up; 128 -> 31.6 rounds up
}

TEST_CASE("rgb image source refuses rows outside the image") {
  RgbImage image(3, 2);
  RgbImageSource source(image);
  std::vector<Color18> row(3), shortRow(2);
  CHECK_THROWS_AS(source.row(2, row), Error);
  CHECK_THROWS_AS(source.row(-1, row), Error);
  CHECK_THROWS_AS(source.row(0, shortRow), Error);
}
