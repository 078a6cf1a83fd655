// Random and mutated streams: the emulator must neither crash, hang nor read
// out of bounds (checked with -fsanitize=address,undefined), and must count what it
// could not use. Time per byte is bounded by construction (every byte is
// consumed once; the costliest single command, a 65536-point panel fill, is
// bounded) and checked here only as "finishes", never timed.
#include <catch2/catch.hpp>

#include <random>

#include "tests/devices/tek4125/tek_test_support.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

// Bytes biased towards what the decoder cares about: ESC, command letters,
// parameter characters and the control characters it acts on.
std::vector<std::uint8_t> randomStream(std::mt19937& rng, std::size_t n) {
  static const std::string alphabet = "\x1b\x1b\x1b\x1d\x1f\x0c\r%!0LFGPEMRSHUTQZAKVBpz @_`\x7f";
  std::vector<std::uint8_t> out(n);
  for (auto& b : out)
    b = rng() % 2 ? static_cast<std::uint8_t>(alphabet[rng() % alphabet.size()]) : static_cast<std::uint8_t>(rng());
  return out;
}

}  // namespace

TEST_CASE("thousands of random streams decode without failing and are counted") {
  std::mt19937 rng(4125);
  std::uint64_t malformed = 0, unknown = 0, commands = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto bytes = randomStream(rng, 50 + rng() % 400);
    Tek4125Profile profile;
    profile.planes = trial % 2 ? 4 : 8;
    Tek4125Decoder d(profile);
    d.feed(bytes);
    d.finish();
    REQUIRE(d.report().bytes == bytes.size());
    REQUIRE(d.image().pixels.size() == 1280u * 1024u);
    for (PaletteIndex p : {d.image().pixels.front(), d.image().pixels.back()}) REQUIRE(p < profile.colorMapSize());
    malformed += d.report().malformed;
    unknown += d.report().unknownCommands;
    commands += d.report().commands;
  }
  CHECK(malformed > 1000);
  CHECK(unknown > 1000);
  CHECK(commands > 300);
}

TEST_CASE("mutated driver streams decode without failing, byte by byte too") {
  Tek4125Profile profile;
  profile.planes = 4;
  const auto original = encode(scene(48, 32, 16), profile);
  std::mt19937 rng(1988);
  std::uint64_t problems = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    std::vector<std::uint8_t> bytes = original;
    const int edits = 1 + static_cast<int>(rng() % 8);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % bytes.size();
      switch (rng() % 4) {
        case 0: bytes[at] = static_cast<std::uint8_t>(rng()); break;
        case 1: bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(at)); break;
        case 2: bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), static_cast<std::uint8_t>(rng())); break;
        default: bytes.resize(at + 1); break;  // truncated stream
      }
      if (bytes.empty()) bytes.push_back(0x1b);
    }
    Tek4125Decoder d(profile);
    if (trial % 10 == 0)
      for (std::uint8_t b : bytes) d.feed(std::span<const std::uint8_t>(&b, 1));
    else
      d.feed(bytes);
    d.finish();
    REQUIRE(d.report().bytes == bytes.size());
    problems += d.report().malformed + d.report().unknownCommands;
  }
  CHECK(problems > 500);  // the damage shows in the report
}

TEST_CASE("pathological but legal parameters stay within the screen and bounded work") {
  using namespace lattice::tek4125;
  Bytes s;
  XyEncoder xy;
  appendCommand(s, "RS");  // viewport far beyond the screen
  xy.append(s, 4095, 4095);
  xy.append(s, 4000, 4000);
  appendCommand(s, "RH");
  xy.append(s, 4095, 4095);
  appendCommand(s, "RP");
  appendInt(s, 65535);
  appendInt(s, 300);
  s.insert(s.end(), 300, '_');
  appendCommand(s, "RR");
  xy.append(s, 0, 0);
  xy.append(s, 4095, 4095);
  appendInt(s, -65535);
  appendCommand(s, "TG");  // entries out of range and a ragged array
  appendInt(s, 1);
  const int entries[] = {9999, 1, 2, 3, -5, 1, 2, 3, 7, 200, -100};
  appendIntArray(s, entries);
  appendCommand(s, "MP");
  appendInt(s, -3);
  appendCommand(s, "LP");  // a panel of many points
  xy.append(s, 0, 0);
  appendInt(s, 1);
  for (int i = 0; i < 3000; ++i) {
    appendCommand(s, "LG");
    xy.append(s, (i * 37) % 4096, (i * 91) % 4096);
  }
  appendCommand(s, "LE");
  Tek4125Decoder d(Tek4125Profile{});
  d.feed(s);
  d.finish();
  CHECK(d.report().malformed == 4);  // short RP, two bad TG indices, ragged TG array
  CHECK(d.image().at(0, 1023) != 0);  // the RR reached the screen's corner
}
