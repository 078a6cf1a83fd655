#include <catch2/catch.hpp>

#include "foundation/indexed_image.hpp"

using namespace lattice;

TEST_CASE("the indexed image sink keeps every row where it belongs") {
  IndexedImageSink sink(16);
  CHECK(sink.maxColors() == 16);
  sink.begin({4, 2, {{1, 2, 3}, {4, 5, 6}}});
  std::vector<PaletteIndex> row0{0, 1, 0, 1}, row1{1, 1, 0, 0};
  sink.row(0, row0);
  sink.row(1, row1);
  sink.end();
  const IndexedImage& img = sink.image();
  CHECK(img.at(1, 0) == 1);
  CHECK(img.at(3, 1) == 0);
  CHECK(img.colorAt(0, 1) == Rgb8{4, 5, 6});
  auto rgb = img.toRgb();
  REQUIRE(rgb.size() == 4 * 2 * 3);
  CHECK(rgb[0] == 1);
  CHECK(rgb[3] == 4);
  CHECK_THROWS(sink.row(2, row0));
  std::vector<PaletteIndex> shortRow{0};
  CHECK_THROWS(sink.row(0, shortRow));
}

TEST_CASE("18-bit colour packing and 6<->8 bit conversion") {
  Color18 c = packColor18(63, 0, 31);
  CHECK(red6(c) == 63);
  CHECK(green6(c) == 0);
  CHECK(blue6(c) == 31);
  CHECK(expand6to8(0) == 0);
  CHECK(expand6to8(63) == 255);
  for (unsigned v = 0; v < 64; ++v) CHECK(reduce8to6(expand6to8(v)) == v);
}
