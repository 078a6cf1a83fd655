// Driver -> emulator: the terminal must show the frame the driver was given,
// pixel for pixel in pots, colours within the HLS round trip.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <random>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/error.hpp"
#include "tests/devices/tek4027/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::tek4027;
using namespace lattice::tek4027::test;
using namespace lattice::testing;

namespace {

struct Sent {
  std::vector<std::uint8_t> bytes;
  std::array<int, 256> potOf{};
  Tek4027StreamStats stats;
};

Sent send(const IndexedImage& img, Tek4027Strategy strategy = Tek4027Strategy::Shortest,
          Tek4027Profile profile = {}, Tek4027Orientation orientation = Tek4027Orientation::Rows) {
  MemorySink sink;
  Tek4027Driver driver(sink, profile, strategy, orientation);
  feedFrame(driver, img);
  Sent s;
  s.bytes = sink.data();
  s.stats = driver.stats();
  for (std::size_t i = 0; i < img.colormap.size(); ++i) s.potOf[i] = driver.potForIndex(static_cast<PaletteIndex>(i));
  return s;
}

void checkReproduces(const IndexedImage& img, const Sent& sent, const Tek4027Profile& profile = {}) {
  Tek4027Decoder d(profile);
  d.feed(sent.bytes);
  d.finish();
  REQUIRE(d.report().malformed == 0);
  REQUIRE(d.report().unknownCommands == 0);
  const IndexedImage& screen = d.image();
  long wrongPots = 0, wrongColours = 0, outsideDrawn = 0;
  for (int y = 0; y < screen.height; ++y)  // counted, not REQUIREd per pixel: keeps the suite fast
    for (int x = 0; x < screen.width; ++x) {
      if (x >= img.width || y >= img.height) {
        outsideDrawn += screen.at(x, y) != profile.backgroundPot;
        continue;
      }
      const PaletteIndex want = img.at(x, y);
      if (screen.at(x, y) != sent.potOf[want]) ++wrongPots;
      const Rgb8 a = img.colormap[want], b = screen.colorAt(x, y);
      if (std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > kHlsRoundTripMaxDelta)
        ++wrongColours;
    }
  CHECK(wrongPots == 0);
  CHECK(wrongColours == 0);
  CHECK(outsideDrawn == 0);
}

constexpr Tek4027Strategy kAll[] = {Tek4027Strategy::RowOrder, Tek4027Strategy::ColourOrder,
                                    Tek4027Strategy::Chained, Tek4027Strategy::ChainedRelative,
                                    Tek4027Strategy::Layered, Tek4027Strategy::LayeredChained,
                                    Tek4027Strategy::Shortest};

}  // namespace

constexpr Tek4027Orientation kBoth[] = {Tek4027Orientation::Rows, Tek4027Orientation::RowsUp,
                                        Tek4027Orientation::Columns};

TEST_CASE("every strategy reproduces random 8-colour noise in every orientation") {
  auto img = noiseImage(97, 61, 8, 1);
  for (auto o : kBoth)
    for (auto s : kAll) {
      INFO(strategyName(s) << " along " << orientationName(o));
      checkReproduces(img, send(img, s, {}, o));
    }
}

TEST_CASE("every strategy reproduces gradients, rings and few-colour noise in every orientation") {
  for (const auto& img : {gradientImage(200, 150), ringsImage(160, 120), noiseImage(50, 40, 2, 7),
                          noiseImage(64, 64, 3, 9)}) {
    for (auto o : kBoth)
      for (auto s : kAll) {
        INFO(strategyName(s) << " along " << orientationName(o) << " on " << img.width << "x" << img.height);
        checkReproduces(img, send(img, s, {}, o));
      }
  }
}

TEST_CASE("shortest takes columns when the picture's runs are vertical") {
  // Vertical stripes: one run per column, one per pixel along rows.
  IndexedImage stripes(60, 40, 3);
  stripes.colormap = {{0, 0, 0}, {255, 0, 0}, {0, 0, 255}};
  for (int y = 0; y < stripes.height; ++y)
    for (int x = 0; x < stripes.width; ++x) stripes.at(x, y) = static_cast<PaletteIndex>(x % 3);
  const Sent best = send(stripes);
  CHECK(best.stats.orientation == Tek4027Orientation::Columns);
  CHECK(best.bytes.size() < send(stripes, Tek4027Strategy::LayeredChained).bytes.size() / 4);
  checkReproduces(stripes, best);
  // Its transpose goes along rows.
  IndexedImage bands(40, 60, 3);
  bands.colormap = stripes.colormap;
  for (int y = 0; y < bands.height; ++y)
    for (int x = 0; x < bands.width; ++x) bands.at(x, y) = stripes.at(y, x);
  CHECK(send(bands).stats.orientation != Tek4027Orientation::Columns);
}

TEST_CASE("a single-colour frame is just an erase, and 1x1 frames work") {
  const Tek4027Profile screen;
  auto flat = singleColourImage(screen.width, screen.height, {200, 100, 50});
  auto sent = send(flat);
  checkReproduces(flat, sent);
  CHECK(sent.stats.vectorCommands == 0);
  CHECK(sent.bytes.size() < 60);

  auto dot = noiseImage(1, 1, 1, 3);
  checkReproduces(dot, send(dot));
  // Two colours on a 1x2 frame: one is background, the other one dot.
  IndexedImage pair(1, 2, 2);
  pair.colormap = {{0, 0, 0}, {255, 255, 255}};
  pair.at(0, 1) = 1;
  checkReproduces(pair, send(pair));
}

TEST_CASE("a full-screen noise frame is reproduced in each profile") {
  for (const std::string& name : tek4027PresetNames()) {
    INFO("profile " << name);
    const Tek4027Profile profile = tek4027Preset(name);
    auto img = noiseImage(profile.width, profile.height, 8, 42);
    checkReproduces(img, send(img, Tek4027Strategy::ChainedRelative, profile), profile);
  }
}

TEST_CASE("the most frequent colour becomes the background pot and is not drawn") {
  IndexedImage img(10, 10, 3);
  img.colormap = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  for (auto& p : img.pixels) p = 2;
  img.at(3, 3) = 0;
  img.at(4, 4) = 1;
  auto sent = send(img, Tek4027Strategy::RowOrder);
  CHECK(sent.potOf[2] == 0);
  CHECK(sent.potOf[0] == 1);
  CHECK(sent.potOf[1] == 2);
  CHECK(sent.stats.vectorCommands == 2);
  checkReproduces(img, sent);

  Tek4027Profile profile;
  profile.backgroundPot = 3;
  auto moved = send(img, Tek4027Strategy::Shortest, profile);
  CHECK(moved.potOf[2] == 3);
  checkReproduces(img, moved, profile);
}

TEST_CASE("profile separators, terminators and command character all decode") {
  auto img = ringsImage(80, 60);
  Tek4027Profile profile;
  profile.separator = ',';
  profile.terminator = ';';
  profile.commandChar = '\x1f';
  auto sent = send(img, Tek4027Strategy::Shortest, profile);
  CHECK(std::count(sent.bytes.begin(), sent.bytes.end(), '!') == 0);
  checkReproduces(img, sent, profile);
}

TEST_CASE("long chains split into short commands still reproduce the frame") {
  auto img = ringsImage(90, 70);
  for (int points : {2, 3, 5}) {
    Tek4027Profile profile;
    profile.maxPointsPerCommand = points;
    for (auto s : kAll) {
      INFO(strategyName(s) << " with " << points << " points a command");
      auto sent = send(img, s, profile);
      checkReproduces(img, sent, profile);
      // No vector command carries more than the profile's points.
      std::string text(sent.bytes.begin(), sent.bytes.end());
      std::size_t at = 0, longest = 0;
      while ((at = text.find('!', at)) != std::string::npos) {
        const std::size_t next = std::min(text.find_first_of("!\r", at + 1), text.size());
        if (text.compare(at + 1, 3, "VEC") == 0 || text.compare(at + 1, 3, "RVE") == 0)
          longest = std::max<std::size_t>(longest, static_cast<std::size_t>(
                                                       std::count(text.begin() + static_cast<std::ptrdiff_t>(at),
                                                                  text.begin() + static_cast<std::ptrdiff_t>(next), ' ')));
        at = next;
      }
      CHECK(longest <= static_cast<std::size_t>(2 * points));
      if (s == Tek4027Strategy::LayeredChained) CHECK(longest == static_cast<std::size_t>(2 * points));
    }
  }
}

TEST_CASE("chunking does not change what the emulator shows") {
  auto img = gradientImage(120, 90);
  auto sent = send(img);
  Tek4027Decoder whole;
  whole.feed(sent.bytes);
  whole.finish();
  std::mt19937 rng(5);
  for (int trial = 0; trial < 6; ++trial) {
    Tek4027Decoder pieces;
    std::size_t at = 0;
    while (at < sent.bytes.size()) {
      // One byte at a time in the first trial, random pieces after.
      std::size_t n = trial == 0 ? 1 : 1 + rng() % 97;
      n = std::min(n, sent.bytes.size() - at);
      pieces.feed(std::span<const std::uint8_t>(sent.bytes.data() + at, n));
      at += n;
    }
    pieces.finish();
    CHECK(pieces.image().pixels == whole.image().pixels);
    CHECK(pieces.image().colormap == whole.image().colormap);
    CHECK(pieces.report().commands == whole.report().commands);
    CHECK(pieces.report().bytes == sent.bytes.size());
  }
}

TEST_CASE("shortest is never longer than any strategy, and chaining beats one vector per run") {
  for (const auto& img : {gradientImage(256, 256), ringsImage(256, 256), noiseImage(128, 128, 8, 3)}) {
    const auto best = send(img, Tek4027Strategy::Shortest).bytes.size();
    std::array<std::size_t, 6> sizes{};
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      sizes[i] = send(img, kAll[i]).bytes.size();
      CHECK(best <= sizes[i]);
    }
    CHECK(sizes[1] <= sizes[0]);  // fewer colour switches, same vectors
    if (img.width == 256) CHECK(sizes[3] < sizes[1]);
  }
}

TEST_CASE("the driver refuses frames and palettes the terminal cannot show") {
  MemorySink sink;
  Tek4027Driver driver(sink);
  CHECK(driver.maxColors() == 8);
  CHECK_THROWS_AS(driver.begin({641, 10, eightColours()}), lattice::Error);
  CHECK_THROWS_AS(driver.begin({10, 481, eightColours()}), lattice::Error);
  Palette nine = eightColours();
  nine.push_back({1, 2, 3});
  CHECK_THROWS_AS(driver.begin({10, 10, nine}), lattice::Error);
  CHECK_THROWS_AS(driver.begin({10, 10, {}}), lattice::Error);
  driver.begin({4, 2, eightColours()});
  std::vector<PaletteIndex> row(4, 0);
  CHECK_THROWS_AS(driver.row(1, row), lattice::Error);  // out of order
  std::vector<PaletteIndex> shortRow(3, 0);
  CHECK_THROWS_AS(driver.row(0, shortRow), lattice::Error);
  CHECK_THROWS_AS(driver.end(), lattice::Error);  // rows missing
  CHECK(sink.bytesWritten() == 0);
  Tek4027Profile bad;
  bad.separator = ';';
  CHECK_THROWS_AS(Tek4027Driver(sink, bad), lattice::Error);
}

// Figures for docs/tek4027.md: LATTICE_TEK4027_SIZES=1 prints them.
TEST_CASE("stream sizes of the 512x512 test images") {
  // The compact profile, as the table in docs/tek4027.md was measured (the
  // strict profile's cost is in bench/results/tek4027-wire.txt).
  Tek4027Profile profile = tek4027Preset("compact");
  profile.height = 512;  // the 512x512 figure needs a taller area than compact's 480 rows
  const char* print = std::getenv("LATTICE_TEK4027_SIZES");
  for (const auto& [name, img] : {std::pair{"rings", ringsImage(512, 512)}, std::pair{"gradient", gradientImage(512, 512)},
                                  std::pair{"noise", noiseImage(512, 512, 8, 11)}}) {
    std::size_t best = SIZE_MAX, shortest = 0;
    for (auto s : kAll) {
      if (s != Tek4027Strategy::Shortest)  // Shortest also tries each strategy in the other orientations
        for (auto o : {Tek4027Orientation::RowsUp, Tek4027Orientation::Columns})
          best = std::min(best, send(img, s, profile, o).bytes.size());
      auto sent = send(img, s, profile);
      if (s == Tek4027Strategy::Shortest)
        shortest = sent.bytes.size();
      else
        best = std::min(best, sent.bytes.size());
      if (print != nullptr)
        WARN(name << " " << strategyName(sent.stats.strategy) << " along " << orientationName(sent.stats.orientation)
                  << (s == Tek4027Strategy::Shortest ? " (picked)" : "")
                  << ": " << sent.bytes.size() << " bytes, " << sent.stats.commands << " commands, "
                  << sent.stats.colourSelects << " !COL, " << sent.stats.lineSeconds / 60 << " min at "
                  << profile.line.baud << " baud, " << sent.stats.terminalSeconds / 60 << " min at "
                  << profile.terminalCharsPerSecond << " chars/s");
    }
    CHECK(shortest == best);
  }
}
