#include <catch2/catch.hpp>

#include <set>

#include "lht/lattice_object.hpp"
#include "lht/table.hpp"
#include "util/error.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

std::vector<RasterHit> syntheticHits(int count) {
  // Distinct keys (p_i.z == 0, p_o.z >= 1), with varied s and normals.
  std::vector<RasterHit> hits;
  for (int i = 0; i < count; ++i) {
    RasterHit h;
    h.in = {std::uint8_t(i % 20), std::uint8_t(i / 20 % 20), 0};
    h.out = {std::uint8_t(i / 400 % 20), 19, std::uint8_t(1 + i % 7)};  // z >= 1: never equal to, nor the reverse of, a key
    h.s = (i % 101) / 100.0;
    h.normal = glm::normalize(Vec3d(std::sin(i), std::cos(i), 0.3));
    hits.push_back(h);
  }
  return hits;
}

}  // namespace

TEST_CASE("LHT: entries are the thesis's 14 bytes and quantize as documented") {
  CHECK(sizeof(LhtEntry) == 14);
  CHECK(quantizeS(0.0) == 0);
  CHECK(quantizeS(1.0) == 255);
  CHECK(quantizeS(0.5) == 128);
  CHECK(quantizeNormalComponent(-1.0) == -127);
  CHECK(quantizeNormalComponent(1.0) == 127);
  RasterHit h{{1, 2, 3}, {4, 5, 6}, 0.3, glm::normalize(Vec3d(1, -2, 2))};
  const LhtEntry e = encodeEntry(h);
  CHECK(e.key[0] == 1);
  CHECK(e.key[5] == 6);
  const LhtHit back = decodeEntry(e);
  CHECK(back.s == Approx(0.3).margin(0.5 / 255));
  CHECK(back.normal.y == Approx(-2.0 / 3).margin(1.0 / 127));
}

TEST_CASE("LHT: every entry is found and every absent key misses") {
  for (double load : {0.5, 1.0, 2.0, 4.0}) {
    INFO("load factor " << load);
    const auto hits = syntheticHits(3000);
    const LatticeHashTable table(hits, load);
    CHECK(table.entryCount() == 3000);
    CHECK(table.loadFactor() == Approx(load).epsilon(0.01));
    CHECK(table.bytes() == (table.bucketCount() + table.overflowCount()) * 14);
    for (const RasterHit& h : hits) {
      const auto found = table.find(h.in, h.out);
      REQUIRE(found);
      CHECK(found->s == Approx(h.s).margin(0.5 / 255));
      CHECK(found->normal.x == Approx(h.normal.x).margin(1.0 / 127));
      CHECK_FALSE(table.find(h.out, h.in));  // reversed: a different pair
    }
    CHECK_FALSE(table.find({200, 200, 200}, {1, 1, 1}));
    CHECK_FALSE(table.find({0, 0, 0}, {0, 0, 0}));  // the empty-slot marker is never a key
    const ChainStats chains = table.chainStats();
    std::uint64_t total = 0;
    for (std::size_t k = 0; k < chains.chainLengthHistogram.size(); ++k) total += k * chains.chainLengthHistogram[k];
    CHECK(total == 3000);
  }
}

TEST_CASE("LHT: a table of a real lattice, its size and chains") {
  const LatticeObject sphere = sphereObject(0.5);
  const LatticeBox box(sphere.bounds, 1.0, 2.0);
  RasterOptions options;
  options.progress = false;
  const RasterResult raster = rasterize(box, *sphere.primitive, options);
  const LatticeHashTable table(raster.hits);
  CHECK(table.entryCount() == raster.hits.size());
  CHECK(table.bytesPerEntry() >= 14.0);
  CHECK(table.bytesPerEntry() < 17.0);  // load factor 2: ~15.0 expected
  for (const RasterHit& h : raster.hits) CHECK(table.find(h.in, h.out));
}

TEST_CASE("LHT: slots from a file are checked before they are trusted") {
  const auto hits = syntheticHits(100);
  const LatticeHashTable table(hits, 2.0);
  CHECK_NOTHROW(LatticeHashTable(table.slots(), table.bucketCount(), table.entryCount()));
  CHECK_THROWS_AS(LatticeHashTable(table.slots(), table.bucketCount(), table.entryCount() + 1), Error);
  CHECK_THROWS_AS(LatticeHashTable(table.slots(), 0, table.entryCount()), Error);
  CHECK_THROWS_AS(LatticeHashTable(table.slots(), table.slots().size() + 1, table.entryCount()), Error);
  // A chain that loops back on itself must be refused, not followed forever.
  auto slots = table.slots();
  for (std::size_t i = table.bucketCount(); i < slots.size(); ++i) {
    const std::uint32_t self = static_cast<std::uint32_t>(i);
    for (int b = 0; b < 4; ++b) slots[i].next[b] = static_cast<std::uint8_t>(self >> (8 * b));
    break;
  }
  REQUIRE(table.overflowCount() > 0);
  CHECK_THROWS_AS(LatticeHashTable(slots, table.bucketCount(), table.entryCount()), Error);
}
