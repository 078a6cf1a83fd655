// Adler-32 by blocks (io/adler32.hpp) against zlib's own, byte for byte: every
// length around the 32-byte blocks and the 5536-byte chunks, bytes at their
// largest (where a lane would overflow first), carried-on checks, and both
// paths (the portable one is zlib's; the vector one is the claim).
#include <catch2/catch.hpp>

#include <zlib.h>

#include <cstdint>
#include <random>
#include <vector>

#include "io/adler32.hpp"

using namespace lattice::io;

namespace {

std::uint32_t zlibAdler(std::uint32_t adler, const std::vector<std::uint8_t>& bytes, std::size_t from, std::size_t size) {
  return static_cast<std::uint32_t>(adler32_z(adler, bytes.data() + from, size));
}

struct AutoAdlerPathOnExit {
  ~AutoAdlerPathOnExit() { forceAdlerPath(AdlerPath::Auto); }
};

}  // namespace

TEST_CASE("Adler-32 by blocks equals zlib's at every length, start and offset", "[io][png]") {
  const AdlerPath path = GENERATE(AdlerPath::Auto, AdlerPath::Portable);
  forceAdlerPath(path);
  AutoAdlerPathOnExit restore;
  std::mt19937 random(11);
  std::vector<std::uint8_t> noise(3 * 5536 + 100), ones(3 * 5536 + 100, 0xff);
  for (auto& b : noise) b = static_cast<std::uint8_t>(random());
  for (const std::vector<std::uint8_t>* bytes : {&noise, &ones}) {
    for (std::size_t size : {0, 1, 31, 32, 33, 63, 64, 65, 5535, 5536, 5537, 2 * 5536 + 31, 3 * 5536 + 99}) {
      for (std::size_t offset : {0, 1, 7}) {  // unaligned loads
        if (offset + size > bytes->size()) continue;
        INFO("size " << size << " offset " << offset);
        CHECK(adler32Update(1, bytes->data() + offset, size) == zlibAdler(1, *bytes, offset, size));
      }
    }
  }
  // Carried on from a check taken elsewhere, with both halves near the modulus.
  for (std::uint32_t start : {0x0001u, 0xfff0fff0u, 0x1234abcdu % (65521u << 16)}) {
    INFO("start " << start);
    CHECK(adler32Update(start, ones.data(), ones.size()) == zlibAdler(start, ones, 0, ones.size()));
    CHECK(adler32Update(start, noise.data(), 4099) == zlibAdler(start, noise, 0, 4099));
  }
}

TEST_CASE("Adler-32 by blocks cut anywhere gives the check of the whole", "[io][png]") {
  std::mt19937 random(5);
  std::vector<std::uint8_t> bytes(20000);
  for (auto& b : bytes) b = static_cast<std::uint8_t>(random() % 7 == 0 ? 0xff : random());
  const std::uint32_t whole = zlibAdler(1, bytes, 0, bytes.size());
  for (std::size_t cut : {1, 32, 5000, 5536, 11111, 19999}) {
    const std::uint32_t first = adler32Update(1, bytes.data(), cut);
    CHECK(adler32Update(first, bytes.data() + cut, bytes.size() - cut) == whole);
  }
}
