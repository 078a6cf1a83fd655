// app/stream_check: which device's stream the first bytes are, as `send`
// and `show` ask before acting. Each device's own stream names that device
// (the 4014's too, which the 4125's recogniser also takes); random bytes and
// a file with a magic number name none.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "app/stream_check.hpp"
#include "devices/device.hpp"
#include "tests/support/golden.hpp"

using lattice::testing::goldenPath;

namespace {

std::vector<std::uint8_t> head(const std::string& golden) {
  std::ifstream in(goldenPath(golden), std::ios::binary);
  std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  REQUIRE_FALSE(bytes.empty());
  if (bytes.size() > lattice::devices::kRecogniseBytes) bytes.resize(lattice::devices::kRecogniseBytes);
  return bytes;
}

}  // namespace

TEST_CASE("each device's stream names its device", "[show][send]") {
  struct Case {
    const char* golden;
    const char* device;
  };
  for (const Case c : {Case{"tek4125/scene24x16_4planes.tek", "tek4125"}, Case{"tek4027/rings-48x32.tek", "tek4027"},
                       Case{"tek4014/rings-96x64.tek", "tek4014"}, Case{"tek4014/rings-96x64-12bit.tek", "tek4014"},
                       Case{"tek4014/gradient-64x40-ordered.tek", "tek4014"}, Case{"sixel/rings-48x32.six", "sixel"},
                       Case{"sixel/noise-64x30-256.six", "sixel"}}) {
    INFO(c.golden);
    CHECK(lattice::app::recogniseDevice(head(c.golden)) == c.device);
  }
}

TEST_CASE("random bytes and files with a magic number are no device's stream", "[show][send]") {
  // 2,000 random heads of 4 KiB: a recogniser that takes one in a hundred
  // fails here all but certainly.
  std::mt19937 rng(1988);
  std::size_t taken = 0;
  std::vector<std::uint8_t> bytes(lattice::devices::kRecogniseBytes);
  for (int i = 0; i < 2000; ++i) {
    for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(rng() >> 24);
    const std::string device = lattice::app::recogniseDevice(bytes);
    if (!device.empty()) {
      ++taken;
      UNSCOPED_INFO("head " << i << " taken by " << device);
    }
  }
  CHECK(taken == 0);
  // A PNG signature, then 7-bit text the sixel recogniser takes: a PNG still.
  const std::string png = "\x89PNG\r\n\x1a\n\x1bPq#0;2;0;0;0#0" + std::string(200, '~') + "\x1b\\";
  const std::vector<std::uint8_t> pngBytes(png.begin(), png.end());
  CHECK(lattice::app::recogniseDevice(pngBytes).empty());
  CHECK(lattice::app::describeContent(pngBytes) == "a PNG image");
}
