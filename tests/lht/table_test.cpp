#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "lht/lattice_object.hpp"
#include "lht/table.hpp"
#include "foundation/error.hpp"

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

TEST_CASE("LHT: the thesis entry is 14 bytes laid out as sec. 2.3 says") {
  CHECK(entryBytes(LhtPrecision::Thesis) == 14);
  CHECK(quantizeFraction(0.0, 255) == 0);
  CHECK(quantizeFraction(1.0, 255) == 255);
  CHECK(quantizeFraction(0.5, 255) == 128);
  CHECK(quantizeNormalComponent(-1.0) == -127);
  CHECK(quantizeNormalComponent(1.0) == 127);
  const RasterHit h{{1, 2, 3}, {4, 5, 6}, 0.3, glm::normalize(Vec3d(1, -2, 2))};
  std::uint8_t e[14] = {};
  encodeEntry(h, LhtPrecision::Thesis, e);
  // key, s * 255 rounded (76.5 -> 77), then n * 127 rounded per component, signed.
  const std::uint8_t expected[10] = {1, 2, 3, 4, 5, 6, 77, 42, std::uint8_t(-85), 85};
  CHECK(std::equal(expected, expected + 10, e));
  const LhtHit back = decodeEntry(e, LhtPrecision::Thesis);
  CHECK(back.s == Approx(0.3).margin(0.5 / 255));
  CHECK(back.normal.y == Approx(-2.0 / 3).margin(1.0 / 127));
}

TEST_CASE("LHT: every entry is found and every absent key misses at every precision") {
  for (const LhtPrecisionInfo& form : kLhtPrecisions)
  for (double load : {0.5, 1.0, 2.0, 4.0}) {
    INFO(form.name << ", load factor " << load);
    const auto hits = syntheticHits(3000);
    const LatticeHashTable table(hits, form.precision, load);
    CHECK(table.precision() == form.precision);
    CHECK(table.entryCount() == 3000);
    CHECK(table.loadFactor() == Approx(load).epsilon(0.01));
    CHECK(table.entryStride() == form.entryBytes);
    CHECK(table.bytes() == (table.bucketCount() + table.overflowCount()) * form.entryBytes);
    const double normalError = 2.0 * std::sin(form.maxNormalErrorDegrees * std::numbers::pi / 360.0);  // chord
    for (const RasterHit& h : hits) {
      const auto found = table.find(h.in, h.out);
      REQUIRE(found);
      CHECK(std::abs(found->s - h.s) <= form.maxSError);
      CHECK(glm::length(found->normal - h.normal) <= normalError);
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

TEST_CASE("LHT: a table of a real lattice at every precision: its size and chains") {
  const LatticeObject sphere = sphereObject(0.5);
  const LatticeBox box(sphere.bounds, 1.0, 2.0);
  RasterOptions options;
  options.progress = false;
  const RasterResult raster = rasterize(box, *sphere.primitive, options);
  const LatticeHashTable thesis(raster.hits);
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    const LatticeHashTable table(raster.hits, form.precision);
    CHECK(table.entryCount() == raster.hits.size());
    // Same hashing, same chains: only the stride differs between forms.
    CHECK(table.bucketCount() == thesis.bucketCount());
    CHECK(table.overflowCount() == thesis.overflowCount());
    CHECK(table.bytes() == thesis.slotCount() * form.entryBytes);
    const double e = double(form.entryBytes);
    CHECK(table.bytesPerEntry() >= e);
    CHECK(table.bytesPerEntry() < e * 17.0 / 14.0);  // load factor 2: ~1.07 slots per entry expected
    for (const RasterHit& h : raster.hits) {
      const auto found = table.find(h.in, h.out);
      REQUIRE(found);
      CHECK(std::abs(found->s - h.s) <= form.maxSError);
    }
  }
}

TEST_CASE("LHT: slots from a file are checked before they are trusted") {
  const auto hits = syntheticHits(100);
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    const LatticeHashTable table(hits, form.precision, 2.0);
    const auto& bytes = table.slotBytes();
    CHECK_NOTHROW(LatticeHashTable(form.precision, bytes, table.bucketCount(), table.entryCount()));
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, table.bucketCount(), table.entryCount() + 1), Error);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, 0, table.entryCount()), Error);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, table.slotCount() + 1, table.entryCount()), Error);
    // Bytes that are not whole entries of this precision.
    std::vector<std::uint8_t> ragged(bytes.begin(), bytes.end() - 1);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, ragged, table.bucketCount(), table.entryCount()), Error);
    // A chain that loops back on itself must be refused, not followed forever.
    REQUIRE(table.overflowCount() > 0);
    std::vector<std::uint8_t> looped = bytes;
    const std::uint64_t first = table.bucketCount();
    storeLittleEndian32(looped.data() + (first + 1) * form.entryBytes - kEntryNextBytes,
                        static_cast<std::uint32_t>(first));
    CHECK_THROWS_AS(LatticeHashTable(form.precision, looped, table.bucketCount(), table.entryCount()), Error);
  }
}

TEST_CASE("LHT: the table reserves exactly its slots and its expected size is close") {
  // syntheticHits keeps keys distinct up to 8000 (20 x 20 x 20 inputs).
  const std::vector<RasterHit> hits = syntheticHits(8000);
  for (const LhtPrecisionInfo& info : kLhtPrecisions) {
    INFO(info.name);
    const LatticeHashTable table(hits, info.precision);
    // No growth slack: the overflow area was sized before it was filled.
    CHECK(table.slotBytes().capacity() == table.slotBytes().size());
    CHECK(LatticeHashTable::slotsFor(hits, table.bucketCount()) == table.slotCount());
    // The budget's prediction (before any table exists) within 2 %.
    const double expected = double(LatticeHashTable::expectedBytes(hits.size(), info.precision));
    CHECK(std::abs(expected / double(table.bytes()) - 1.0) < 0.02);
  }
  CHECK(LatticeHashTable::expectedBytes(0, LhtPrecision::Thesis) == 14);  // one empty bucket's slot at most
}

TEST_CASE("LHT: a table read in place (the firmware's flash) answers like the one it was copied from") {
  const auto hits = syntheticHits(2000);
  const LatticeHashTable built(hits, LhtPrecision::Thesis);
  const std::vector<std::uint8_t> flash = built.slotBytes();  // stands in for the baked constant array
  const LatticeHashTable view =
      LatticeHashTable::inPlace(built.precision(), flash, built.bucketCount(), built.entryCount());
  CHECK(view.slotBytes().empty());  // nothing copied
  CHECK(view.slotView().data() == flash.data());
  CHECK(view.bytes() == built.bytes());
  for (const RasterHit& h : hits) {
    REQUIRE(view.findEntry(h.in, h.out) != nullptr);
    CHECK(std::equal(view.findEntry(h.in, h.out), view.findEntry(h.in, h.out) + view.entryStride(),
                     built.findEntry(h.in, h.out)));
  }
  // Checked like a file's slots: a wrong entry count is refused.
  CHECK_THROWS_AS(LatticeHashTable::inPlace(built.precision(), flash, built.bucketCount(), built.entryCount() + 1),
                  Error);
}
