// Hostile streams: random bytes from the command alphabet and mutations of a
// real driver stream. The emulator must consume everything, keep its
// framebuffer in shape and never crash or hang (the suite's timeout would
// catch a hang; the sanitizer build catches out-of-bounds access).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "tests/devices/tek4027/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::tek4027;
using namespace lattice::tek4027::test;

namespace {

void checkSane(const std::vector<std::uint8_t>& stream, std::mt19937& rng) {
  Tek4027Decoder d;
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::size_t n = std::min<std::size_t>(1 + rng() % 64, stream.size() - at);
    d.feed(std::span<const std::uint8_t>(stream.data() + at, n));
    at += n;
  }
  d.finish();
  REQUIRE(d.report().bytes == stream.size());
  const Tek4027Profile profile;  // the default (strict) screen
  REQUIRE(d.image().width == profile.width);
  REQUIRE(d.image().height == profile.height);
  REQUIRE(d.image().pixels.size() == static_cast<std::size_t>(profile.width) * static_cast<std::size_t>(profile.height));
  REQUIRE(d.image().colormap.size() == 8);
  const auto& px = d.image().pixels;
  REQUIRE(std::all_of(px.begin(), px.end(), [](PaletteIndex p) { return p < 8; }));
  REQUIRE(d.currentPot() >= 0);
  REQUIRE(d.currentPot() < 8);
  REQUIRE(std::labs(d.beamX()) <= Tek4027Decoder::kMaxCoordinate);
  REQUIRE(std::labs(d.beamY()) <= Tek4027Decoder::kMaxCoordinate);
  // The per-name table is capped: a stream of made-up names cannot grow it.
  REQUIRE(d.report().unknownByName.size() <= Tek4027Decoder::kMaxUnknownNames + 1);
}

}  // namespace

TEST_CASE("random streams over the command alphabet never break the emulator") {
  const std::string alphabet = "!!!!;;\r\n ,,-+0123456789VECRVCOLMAPMIXERAGCOMWORGRAMONLINCLEREPHKcvge\x1f\x00\x7f\xff";
  std::mt19937 rng(20261122);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::uint8_t> stream(rng() % 400);
    for (auto& b : stream)
      b = rng() % 8 == 0 ? static_cast<std::uint8_t>(rng()) : static_cast<std::uint8_t>(alphabet[rng() % alphabet.size()]);
    checkSane(stream, rng);
  }
}

TEST_CASE("mutated driver streams never break the emulator") {
  const std::string text = test::driveFrame(testing::ringsImage(64, 48), Tek4027Profile{});
  const std::vector<std::uint8_t> original(text.begin(), text.end());
  REQUIRE(original.size() > 500);

  std::mt19937 rng(4027);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::uint8_t> s = original;
    const int edits = 1 + static_cast<int>(rng() % 8);
    for (int e = 0; e < edits && !s.empty(); ++e) {
      const std::size_t at = rng() % s.size();
      switch (rng() % 5) {
        case 0: s[at] = static_cast<std::uint8_t>(rng()); break;                          // flip a byte
        case 1: s.erase(s.begin() + static_cast<std::ptrdiff_t>(at)); break;             // drop one
        case 2: s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), "9999999"[rng() % 7]); break;
        case 3: s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), '-'); break;       // signs
        case 4: s.resize(at); break;                                                      // cut off
      }
    }
    checkSane(s, rng);
  }
}
