#include <catch2/catch.hpp>

#include <vector>

#include "quantize/histogram.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::quantize;

TEST_CASE("histogram counts every pixel of a row in its 18-bit cell") {
  Histogram h;
  std::vector<Color18> row{packColor18(1, 2, 3), packColor18(1, 2, 3), packColor18(63, 63, 63), 0};
  h.addRow(row);
  CHECK(h.count(packColor18(1, 2, 3)) == 2);
  CHECK(h.count(packColor18(63, 63, 63)) == 1);
  CHECK(h.count(0) == 1);
  CHECK(h.count(packColor18(1, 2, 4)) == 0);
  CHECK(h.totalPixels() == 4);
  CHECK(h.distinctColors() == 3);
}

TEST_CASE("histogram sampling takes every Nth column from column 0") {
  Histogram h;
  std::vector<Color18> row;
  for (unsigned i = 0; i < 10; ++i) row.push_back(packColor18(i, 0, 0));
  h.addRowSampled(row, 3);
  CHECK(h.totalPixels() == 4);  // columns 0, 3, 6, 9
  CHECK(h.count(packColor18(3, 0, 0)) == 1);
  CHECK(h.count(packColor18(4, 0, 0)) == 0);
  CHECK_THROWS_AS(h.addRowSampled(row, 0), Error);
}

TEST_CASE("histogram refuses colours wider than 18 bits instead of writing out of bounds") {
  Histogram h;
  CHECK_THROWS_AS(h.add(Color18{1} << 18), Error);
  CHECK(h.totalPixels() == 0);
}

TEST_CASE("histogram hands its 1 MiB of counters over for reuse") {
  Histogram h;
  h.add(5);
  std::vector<std::uint32_t> storage = h.releaseStorage();
  CHECK(storage.size() == Histogram::kCells);
  CHECK(storage[5] == 1);
  CHECK(Histogram::kBytes == 1024 * 1024);
  CHECK_THROWS_AS(h.add(5), Error);
}
