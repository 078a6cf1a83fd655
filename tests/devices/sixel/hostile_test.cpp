// The emulator against streams no driver would write: it never throws, stays
// within its size caps and work budget, counts what it skips, and does not
// depend on how the bytes are chunked.
#include <catch2/catch.hpp>

#include <random>

#include "devices/sixel/sixel_forms.hpp"
#include "devices/work_budget.hpp"
#include "tests/devices/sixel/sixel_support.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::sixel;
using namespace lattice::sixel::test;

namespace {

SixelDecoder decode(std::string_view s, SixelProfile profile = {}) {
  SixelDecoder d(profile);
  d.feed(bytesOf(s));
  d.finish();
  return d;
}

}  // namespace

TEST_CASE("huge repeats and sizes are clipped to the terminal and cost only what shows") {
  const auto d = decode("\x1bPq\"1;1;99999;99999#1;2;100;0;0#1!999999999~-!4000000000~\x1b\\");
  CHECK(d.image().width == 1000);
  CHECK(d.image().height == 1000);
  CHECK(d.report().malformed == 1);  // the declared size beyond the terminal
  CHECK(d.report().pixelWork <= 1000ull * 1000 + 2 * 6 * 1000);
  CHECK(d.image().at(999, 11) == 1);
}

TEST_CASE("the work budget stops drawing and says so") {
  std::string s = "\x1bPq#1";
  for (int i = 0; i < 200; ++i) s += "!1000~$";
  SixelDecoder d;
  for (std::uint64_t round = 0; round < 1000 && !d.report().overBudget; ++round) d.feed(bytesOf(s));
  CHECK(d.report().overBudget);
  CHECK(d.report().pixelWork <= kPixelWorkBudget);
}

TEST_CASE("garbage, truncation and unknown sequences are counted, never thrown") {
  CHECK(decode("hello").report().malformed == 1);
  CHECK(decode("\x1b[?25l").report().unknownCommands == 1);
  CHECK(decode("\x1bP1$r\x1b\\").report().unknownCommands == 1);
  CHECK(decode("\x1bPq#1;2;101;0;0").report().malformed == 2);  // out of range, and cut off
  CHECK(decode("\x1bPq!~\x1b\\").report().malformed == 0);  // "!~": count 0, xterm draws nothing
  CHECK(decode("\x1bPq!5#\x1b\\").report().malformed == 1);  // a repeat of no sixel
  CHECK(decode("\x1bPq\"0;1;5;5\x1b\\").report().malformed == 1);
  const auto cancelled = decode("\x1bPq#1~~\x18~~");
  CHECK(cancelled.report().malformed == 2);  // CAN, then stray text
  CHECK(cancelled.image().width == 2);
  // Registers past the last wrap around, as in xterm.
  const auto wrapped = decode("\x1bPq#17;2;0;100;0#17~\x1b\\");
  CHECK(wrapped.image().at(0, 0) == 1);
  CHECK(wrapped.image().colormap[1] == Rgb8{0, 255, 0});
}

TEST_CASE("HLS registers use DEC's hue circle (0 blue, 120 red, 240 green)") {
  const auto d = decode("\x1bPq#1;1;0;50;100#2;1;120;50;100#3;1;240;50;100\x1b\\");
  CHECK(d.image().colormap[1] == Rgb8{0, 0, 255});
  CHECK(d.image().colormap[2] == Rgb8{255, 0, 0});
  CHECK(d.image().colormap[3] == Rgb8{0, 255, 0});
}

TEST_CASE("any chunking decodes the same, random bytes included") {
  const auto stream = driveFrame(testing::ringsImage(50, 20));
  std::mt19937 rng(9);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<std::uint8_t> bytes = stream;
    if (trial % 2) for (int i = 0; i < 20; ++i) bytes[rng() % bytes.size()] = static_cast<std::uint8_t>(rng());
    SixelDecoder whole;
    whole.feed(bytes);
    whole.finish();
    SixelDecoder pieces;
    for (std::size_t at = 0; at < bytes.size();) {
      const std::size_t n = std::min<std::size_t>(1 + rng() % 7, bytes.size() - at);
      pieces.feed(std::span<const std::uint8_t>(bytes).subspan(at, n));
      at += n;
    }
    pieces.finish();
    CHECK(whole.image().pixels == pieces.image().pixels);
    CHECK(whole.report().malformed == pieces.report().malformed);
  }
}
