// The occupancy bitmap in front of the hash table (lht/table/occupancy_filter.hpp):
// it never hides a held key, it answers most absent keys on its own, and a
// table with it finds exactly what its slots hold (built, read from a file's
// slots, or read in place with no bitmap at all).
#include <catch2/catch.hpp>

#include <cstring>
#include <set>

#include "lht/table/hash_table.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

// Distinct keys spread over a 24-cell box's points, from a fixed-seed xorshift.
std::vector<RasterHit> scatteredHits(int count) {
  std::set<std::uint64_t> seen;
  std::vector<RasterHit> hits;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  const auto next = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return std::uint8_t(state % 25);
  };
  while (int(hits.size()) < count) {
    RasterHit h;
    h.in = {next(), next(), next()};
    h.out = {next(), next(), next()};
    if (h.in == h.out || !seen.insert(LatticeHashTable::keyOf(h.in, h.out)).second) continue;
    h.s = 0.25;
    h.normal = Vec3d(0, 0, 1);
    hits.push_back(h);
  }
  return hits;
}

// Pairs of the 25^3 grid (one a point, the other a permutation of it) that are not held.
template <typename F>
void forEachAbsentPair(const LatticeHashTable& table, F&& f) {
  for (std::uint8_t a = 0; a < 25; ++a)
    for (std::uint8_t b = 0; b < 25; ++b)
      for (std::uint8_t c = 0; c < 25; ++c) {
        const LatticePoint in{a, b, c}, out{std::uint8_t(24 - c), a, b};
        if (in == out || table.findKey(LatticeHashTable::keyOf(in, out))) continue;
        f(in, out);
      }
}

}  // namespace

TEST_CASE("occupancy filter: every key added is answered maybe, most others absent") {
  OccupancyFilter filter(1000);
  CHECK(filter.bits() == 8192);  // 8 bits an entry, rounded up to a power of two
  CHECK(filter.bytes() == OccupancyFilter::bytesFor(1000));
  std::uint64_t state = 1;
  std::vector<std::uint64_t> keys;
  for (int n = 0; n < 1000; ++n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    keys.push_back(state >> 16);
    filter.add(keys.back());
  }
  for (std::uint64_t key : keys) REQUIRE(filter.mayHold(key));
  int maybe = 0, asked = 0;
  for (std::uint64_t key = 1; key < 200000; key += 7, ++asked) maybe += filter.mayHold(key) ? 1 : 0;
  // One hash at 8.2 bits a key: about 1 - e^(-1/8.2) = 11.5 % of absent keys pass.
  CHECK(double(maybe) / asked < 0.16);
  CHECK(maybe > 0);
}

TEST_CASE("occupancy filter: an empty filter answers maybe to every key") {
  const OccupancyFilter none;
  CHECK(none.empty());
  CHECK(none.mayHold(0x123456789ull));
  CHECK(none.bytes() == 0);
}

TEST_CASE("occupancy filter: the hash table finds the same entries with and without it") {
  const auto hits = scatteredHits(3000);
  const LatticeHashTable built(hits, LhtPrecision::Thesis);
  const LatticeHashTable fromFile(built.precision(), built.slotBytes(), built.capacity(), built.entryCount());
  const std::vector<std::uint8_t> flash = built.slotBytes();
  const LatticeHashTable inPlace = LatticeHashTable::inPlace(built.precision(), flash, built.capacity(),
                                                             built.entryCount());
  CHECK(built.filter().bytes() == OccupancyFilter::bytesFor(3000));
  CHECK(fromFile.filter().bits() == built.filter().bits());
  CHECK(inPlace.filter().empty());  // the firmware's flash: no bitmap in RAM
  CHECK(LatticeHashTable::expectedMemory(3000, LhtPrecision::Thesis) == built.bytes() + built.filter().bytes());
  for (const RasterHit& h : hits) {
    const std::uint8_t* e = built.findEntry(h.in, h.out);
    REQUIRE(e == built.findKey(LatticeHashTable::keyOf(h.in, h.out)));
    REQUIRE(fromFile.findEntry(h.in, h.out) != nullptr);
    CHECK(std::memcmp(fromFile.findEntry(h.in, h.out), e, built.entryStride()) == 0);
    CHECK(inPlace.findEntry(h.in, h.out) != nullptr);
  }
  // Absent pairs: no entry through any of the three, and most never reach the slots.
  int absent = 0, answered = 0;
  forEachAbsentPair(built, [&](const LatticePoint& in, const LatticePoint& out) {
    ++absent;
    CHECK(built.findEntry(in, out) == nullptr);
    CHECK(fromFile.findEntry(in, out) == nullptr);
    CHECK(inPlace.findEntry(in, out) == nullptr);
    const std::uint64_t key = LatticeHashTable::keyOf(in, out);
    answered += built.filter().mayHold(key) ? 0 : 1;
    CHECK(built.filter().mayHold(key) == fromFile.filter().mayHold(key));
  });
  REQUIRE(absent > 10000);
  CHECK(double(answered) / absent > 0.84);  // about e^(-3000/32768) = 91 % expected
}
