// Driver -> emulator: the terminal shows the frame the driver was given,
// register for register, colours within the percent round trip; and the
// band encoder's runs stay between what each pass must and may set.
#include <catch2/catch.hpp>

#include <cstdlib>

#include "devices/gun_percent.hpp"
#include "devices/sixel/sixel_band.hpp"
#include "devices/sixel/sixel_forms.hpp"
#include "foundation/error.hpp"
#include "tests/devices/sixel/sixel_support.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::sixel;
using namespace lattice::sixel::test;

namespace {

void checkReproduces(const IndexedImage& img, const SixelProfile& profile = {}) {
  const auto stream = driveFrame(img, profile);
  SixelDecoder d(profile);
  d.feed(stream);
  d.finish();
  REQUIRE(d.report().malformed == 0);
  REQUIRE(d.report().unknownCommands == 0);
  const IndexedImage& screen = d.image();
  REQUIRE(screen.width == img.width);
  REQUIRE(screen.height == img.height);
  long wrongRegisters = 0, wrongColours = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      wrongRegisters += screen.at(x, y) != img.at(x, y);
      const Rgb8 a = img.colorAt(x, y), b = screen.colorAt(x, y);
      wrongColours += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) >
                      devices::kPercentRoundTripMaxDelta;
    }
  CHECK(wrongRegisters == 0);
  CHECK(wrongColours == 0);
}

// The sixel values encodeRuns wrote, one per column, expanded from its runs.
std::vector<std::uint8_t> expandRuns(const std::string& runs) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < runs.size();) {
    std::size_t count = 1;
    if (runs[i] == '!') {
      std::size_t end = i + 1;
      while (std::isdigit(static_cast<unsigned char>(runs[end]))) ++end;
      count = std::stoul(runs.substr(i + 1, end - i - 1));
      i = end;
    }
    out.insert(out.end(), count, static_cast<std::uint8_t>(runs[i] - 0x3F));
    ++i;
  }
  return out;
}

}  // namespace

TEST_CASE("8 bits -> percent -> 8 bits stays within the stated bound") {
  int worst = 0;
  for (int v = 0; v < 256; ++v) worst = std::max(worst, std::abs(devices::eightOfPercent(devices::percentOf8(static_cast<std::uint8_t>(v))) - v));
  CHECK(worst <= devices::kPercentRoundTripMaxDelta);
  CHECK(devices::percentOf8(0) == 0);
  CHECK(devices::percentOf8(255) == 100);
  CHECK(devices::eightOfPercent(100) == 255);
}

TEST_CASE("runs: each written sixel lies between must and may, and long runs are repeats") {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 500; ++trial) {
    const std::size_t w = 1 + rng() % 80;
    std::vector<std::uint8_t> must(w), may(w);
    for (std::size_t x = 0; x < w; ++x) {
      must[x] = static_cast<std::uint8_t>(rng() % 64 & rng() % 64);
      may[x] = static_cast<std::uint8_t>(must[x] | (rng() % 64));
    }
    std::string out;
    encodeRuns(must, may, out);
    const auto values = expandRuns(out);
    std::size_t end = w;
    while (end > 0 && must[end - 1] == 0) --end;
    REQUIRE(values.size() == end);
    for (std::size_t x = 0; x < end; ++x) {
      CHECK((values[x] & must[x]) == must[x]);
      CHECK((values[x] & ~may[x]) == 0);
    }
  }
  std::string out;
  const std::vector<std::uint8_t> full(100, 63);
  encodeRuns(full, full, out);
  CHECK(out == "!100~");
  out.clear();
  const std::vector<std::uint8_t> three{1, 1, 1};
  encodeRuns(three, three, out);
  CHECK(out == "@@@");
  out.clear();
  // Free bits let one run cover columns whose musts differ.
  const std::vector<std::uint8_t> must{1, 2, 4, 8}, may{63, 63, 63, 63};
  encodeRuns(must, may, out);
  CHECK(out == "!4N");  // 1|2|4|8 = 15, '?' + 15
}

TEST_CASE("the stream has the sourced opening, registers in percent and ST") {
  IndexedImage img(3, 2, 2);
  img.colormap = {{0, 0, 0}, {255, 128, 0}};
  img.at(1, 0) = 1;
  const std::string s = text(driveFrame(img));
  CHECK(s.rfind("\x1bPq\"1;1;3;2#0;2;0;0;0#1;2;100;50;0", 0) == 0);
  CHECK(s.substr(s.size() - 2) == "\x1b\\");
  SixelProfile p;
  p.p2 = 1;
  CHECK(text(driveFrame(img, p)).rfind("\x1bP0;1q", 0) == 0);
}

TEST_CASE("noise, gradients and rings of 2 to 256 colours come back exactly") {
  SixelProfile wide;
  wide.registers = 256;
  for (int colours : {2, 7, 16}) {
    INFO(colours << " colours");
    checkReproduces(patchyNoise(97, 61, colours, 1, 3));
    checkReproduces(patchyNoise(120, 37, colours, 9, 4));
  }
  checkReproduces(patchyNoise(200, 100, 256, 1, 5), wide);
  checkReproduces(patchyNoise(200, 100, 256, 5, 6), wide);
  checkReproduces(testing::gradientImage(200, 150));
  checkReproduces(testing::ringsImage(161, 119));
  for (int h = 1; h <= 13; ++h) checkReproduces(patchyNoise(5, h, 3, 1, static_cast<std::uint32_t>(h)));
  checkReproduces(testing::singleColourImage(1, 1, {1, 2, 3}));
}

TEST_CASE("one flat band is one repeat, and absent registers cost nothing") {
  IndexedImage flat(500, 12, 16);
  flat.colormap = spreadPalette(16);
  for (auto& p : flat.pixels) p = 9;
  const std::string s = text(driveFrame(flat));
  const std::size_t bands = s.find("#15;2;");
  REQUIRE(bands != std::string::npos);
  // After the register definitions: "#9!500~-!500~" then ST.
  CHECK(s.substr(s.size() - 15) == "#9!500~-!500~\x1b\\");
}

TEST_CASE("frames larger than the profile or with more colours than registers are refused") {
  MemorySink sink;
  SixelDriver driver(sink);
  CHECK_THROWS_AS(driver.begin({1001, 10, spreadPalette(2)}), Error);
  CHECK_THROWS_AS(driver.begin({10, 10, spreadPalette(17)}), Error);
  SixelProfile p;
  CHECK_THROWS_AS(applyOverride(p, "registers=1"), Error);
  CHECK_THROWS_AS(applyOverride(p, "size=3"), Error);
  applyOverride(p, "registers=256");
  CHECK(p.registers == 256);
}

TEST_CASE("passes whose columns do not meet share one line, after the pass that paints under them") {
  // Register 0 everywhere but columns 2-5 (register 1) and 30-33 (register 2):
  // 0 covers the band first, then 1 and 2 go on one line (no second `$`).
  IndexedImage img(40, 6, 3);
  img.colormap = spreadPalette(3);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 40; ++x) img.at(x, y) = x >= 2 && x < 6 ? 1 : x >= 30 && x < 34 ? 2 : 0;
  const std::string s = text(driveFrame(img));
  const std::string band = "#0!40~$??#1!4~!24?#2!4~\x1b\\";
  REQUIRE(s.size() > band.size());
  CHECK(s.substr(s.size() - band.size()) == band);
  checkReproduces(img);
}

TEST_CASE("a segment never overwrites a later register's pixel after that register is drawn") {
  // Noise whose colours interleave at every scale: every cut and packing the
  // encoder tries must still leave each pixel its own register.
  SixelProfile wide;
  wide.registers = 256;
  for (std::uint32_t seed = 20; seed < 40; ++seed) {
    INFO("seed " << seed);
    checkReproduces(patchyNoise(150, 13, 2 + static_cast<int>(seed % 7) * 40, 1 + static_cast<int>(seed % 5), seed),
                    wide);
  }
}

TEST_CASE("flat patches and short last bands come back exactly") {
  // A sweep: large patches make many runs that set all of a band's rows
  // (their edges come from the later registers' groups, not pixel by
  // pixel), and heights that are not multiples of 6 a last band of fewer
  // rows. The case after this one is the one built to fail if such a run's
  // edges were lost.
  SixelProfile wide;
  wide.registers = 256;
  for (std::uint32_t seed = 50; seed < 62; ++seed) {
    INFO("seed " << seed);
    const int height = 7 + static_cast<int>(seed % 6);  // last band of 1..6 rows
    checkReproduces(patchyNoise(180, height, 3 + static_cast<int>(seed % 3) * 6, 12 + static_cast<int>(seed % 4) * 8, seed));
    checkReproduces(patchyNoise(140, height, 60 + static_cast<int>(seed % 3) * 60, 16, seed), wide);
  }
}

TEST_CASE("a run over every row goes before the later register it paints under, though that one starts left of it") {
  // Register 0 fills columns 0-19, register 1 columns 22-39 but for 28-29,
  // register 2 columns 20-21 and 28-29. Register 1's pass is one run over
  // every row, !18~ from column 22, painting under register 2's pixels at
  // 28-29; register 2's one segment (its blank of 6 is never cut) starts
  // at 20, left of it, so only the edge from that run keeps register 2 off
  // the first line: without it the first line would be 2 bytes shorter and
  // register 1 would overwrite columns 28-29. For a last band of fewer rows
  // too, where every row is fewer bits.
  for (int height : {6, 4, 10}) {
    INFO("height " << height);
    IndexedImage img(40, height, 3);
    img.colormap = spreadPalette(3);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < 40; ++x)
        img.at(x, y) = x < 20 ? 0 : x < 22 || (x >= 28 && x < 30) ? 2 : 1;
    checkReproduces(img);
    const std::string band = "#0!20~??#1!18~$!20?#2~~!6?~~";
    const std::string s = text(driveFrame(img));
    if (height == 6) CHECK(s.substr(s.size() - band.size() - 2, band.size()) == band);
  }
}
