#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "lht/raster/lattice_object.hpp"
#include "lht/table/hash_table.hpp"
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
  for (double load : {0.3, 0.5, 0.75, 0.95}) {
    INFO(form.name << ", load limit " << load);
    const auto hits = syntheticHits(3000);
    const LatticeHashTable table(hits, form.precision, load);
    CHECK(table.precision() == form.precision);
    CHECK(table.entryCount() == 3000);
    // The fewest slots within the limit.
    CHECK(table.capacity() == static_cast<std::uint64_t>(std::ceil(3000 / load)));
    CHECK(table.loadFactor() <= load);
    CHECK(table.entryStride() == form.entryBytes - 4);  // no overflow index
    CHECK(table.bytes() == table.capacity() * (form.entryBytes - 4));
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
    const ProbeStats probes = table.probeStats();
    std::uint64_t total = 0;
    for (std::uint64_t n : probes.displacementHistogram) total += n;
    CHECK(total == 3000);
    CHECK(probes.meanHitSlots >= 1.0);
    CHECK(probes.meanMissSlots >= 1.0);
  }
}

TEST_CASE("LHT: a miss costs about what a hit does (ordered hashing)") {
  // Knuth (TAOCP vol. 3, sec. 6.4): at load a, a hit reads (1 + 1/(1-a))/2
  // slots and, unordered, a miss (1 + 1/(1-a)^2)/2 on average, for keys
  // hashed uniformly at random. Ordered, a miss stops where its key would
  // sit: about the hit's cost, well under the unordered miss.
  const auto hits = syntheticHits(6000);  // a = 0.7
  const LatticeHashTable table(hits);
  const double a = table.loadFactor();
  const ProbeStats probes = table.probeStats();
  CHECK(probes.meanHitSlots >= 1.0);
  CHECK(probes.meanHitSlots <= (1 + 1 / (1 - a)) / 2);
  CHECK(probes.meanMissSlots >= 1.0);
  CHECK(probes.meanMissSlots <= 1.5 * (1 + 1 / (1 - a)) / 2);
  CHECK(probes.meanMissSlots < 0.6 * (1 + 1 / ((1 - a) * (1 - a))) / 2);
  CHECK(probes.meanMissSlots * double(table.entryStride()) < 128.0);  // two cache lines
}

TEST_CASE("LHT: the layout does not depend on the order the keys come in") {
  auto hits = syntheticHits(3000);
  const LatticeHashTable forward(hits);
  std::reverse(hits.begin(), hits.end());
  const LatticeHashTable backward(hits);
  std::swap(hits[0], hits[1500]);
  std::rotate(hits.begin(), hits.begin() + 777, hits.end());
  const LatticeHashTable shuffled(hits);
  CHECK(forward.slotBytes() == backward.slotBytes());
  CHECK(forward.slotBytes() == shuffled.slotBytes());
  // Ordered along every run: each key is smaller than the one before it,
  // unless that one is empty or sits at or before its own home.
  const std::size_t stride = forward.entryStride();
  std::uint64_t ordered = 0;
  for (std::uint64_t i = 1; i < forward.capacity(); ++i) {
    const std::uint64_t before = LatticeHashTable::loadKey(&forward.slotBytes()[(i - 1) * stride]);
    const std::uint64_t here = LatticeHashTable::loadKey(&forward.slotBytes()[i * stride]);
    if (here == 0 || before == 0 || LatticeHashTable::homeOf(here, forward.capacity()) == i) continue;
    CHECK(before > here);
    ++ordered;
  }
  CHECK(ordered > 300);  // the check saw runs
}

TEST_CASE("LHT: a table of a real lattice at every precision: its size and probes") {
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
    // Same hashing, same probes: only the stride differs between forms.
    CHECK(table.capacity() == thesis.capacity());
    CHECK(table.probeStats().displacementHistogram == thesis.probeStats().displacementHistogram);
    const double e = double(form.entryBytes - 4);
    CHECK(table.bytesPerEntry() >= e / LatticeHashTable::kMaxLoad);
    CHECK(table.bytesPerEntry() < e / LatticeHashTable::kMaxLoad + 0.01);
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
    const LatticeHashTable table(hits, form.precision);
    const std::size_t stride = table.entryStride();
    const auto& bytes = table.slotBytes();
    const std::uint64_t n = table.capacity();
    CHECK_NOTHROW(LatticeHashTable(form.precision, bytes, n, table.entryCount()));
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, n, table.entryCount() + 1), Error);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, 0, table.entryCount()), Error);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, 1, table.entryCount()), Error);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, bytes, n + 1, table.entryCount()), Error);  // not its slots
    // Bytes that are not whole slots of this precision.
    std::vector<std::uint8_t> ragged(bytes.begin(), bytes.end() - 1);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, ragged, n, table.entryCount()), Error);
    // Find a held slot whose predecessor is empty (the start of a run).
    std::uint64_t runStart = 0;
    while (LatticeHashTable::loadKey(&bytes[runStart * stride]) == 0 ||
           LatticeHashTable::loadKey(&bytes[((runStart + n - 1) % n) * stride]) != 0)
      ++runStart;
    // A key moved one slot on, past an empty slot its look-up stops at: unreachable.
    const std::uint64_t next = (runStart + 1) % n;
    if (LatticeHashTable::loadKey(&bytes[next * stride]) == 0) {
      std::vector<std::uint8_t> moved = bytes;
      std::copy_n(&bytes[runStart * stride], stride, &moved[next * stride]);
      std::fill_n(&moved[runStart * stride], stride, 0);
      const std::uint64_t home = LatticeHashTable::homeOf(LatticeHashTable::loadKey(&bytes[runStart * stride]), n);
      REQUIRE(home == runStart);  // the first of a run sits at its home
      CHECK_THROWS_AS(LatticeHashTable(form.precision, moved, n, table.entryCount()), Error);
    }
    // A key held twice (copied into an empty slot after its own) is refused.
    std::vector<std::uint8_t> twice = bytes;
    std::uint64_t empty = runStart;
    while (LatticeHashTable::loadKey(&bytes[empty * stride]) != 0) empty = (empty + 1) % n;
    std::copy_n(&bytes[runStart * stride], stride, &twice[empty * stride]);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, twice, n, table.entryCount() + 1), Error);
    // Every slot full: a miss would never end.
    std::vector<std::uint8_t> full(bytes.size());
    for (std::uint64_t i = 0; i < n; ++i) full[i * stride] = 1, full[i * stride + 3] = std::uint8_t(i), full[i * stride + 4] = std::uint8_t(i >> 8);
    CHECK_THROWS_AS(LatticeHashTable(form.precision, full, n, n), Error);
  }
}

TEST_CASE("LHT: the table's size is known from its entry count alone") {
  // syntheticHits keeps keys distinct up to 8000 (20 x 20 x 20 inputs).
  for (int count : {1, 2, 3, 699, 700, 701, 6000, 8000}) {
    const std::vector<RasterHit> hits = syntheticHits(count);
    for (const LhtPrecisionInfo& info : kLhtPrecisions) {
      INFO(info.name << ", " << count << " entries");
      const LatticeHashTable table(hits, info.precision);
      CHECK(table.slotBytes().capacity() == table.slotBytes().size());  // no growth slack
      // The budget's prediction (before any table exists) is exact.
      CHECK(LatticeHashTable::expectedBytes(hits.size(), info.precision) == table.bytes());
      CHECK(table.loadFactor() <= LatticeHashTable::kMaxLoad);
    }
  }
  CHECK(LatticeHashTable::capacityFor(1000) == 1429);  // ceil(1000 / 0.7)
  CHECK(LatticeHashTable::capacityFor(701) == 1002);
  CHECK(LatticeHashTable::capacityFor(0) == 2);
  CHECK(LatticeHashTable::capacityFor(1) == 2);         // one slot stays empty
  CHECK(LatticeHashTable::expectedBytes(0, LhtPrecision::Thesis) == 20);  // two empty 10-byte slots
}

TEST_CASE("LHT: a table read in place (the firmware's flash) answers like the one it was copied from") {
  const auto hits = syntheticHits(2000);
  const LatticeHashTable built(hits, LhtPrecision::Thesis);
  const std::vector<std::uint8_t> flash = built.slotBytes();  // stands in for the baked constant array
  const LatticeHashTable view =
      LatticeHashTable::inPlace(built.precision(), flash, built.capacity(), built.entryCount());
  CHECK(view.slotBytes().empty());  // nothing copied
  CHECK(view.slotView().data() == flash.data());
  CHECK(view.bytes() == built.bytes());
  for (const RasterHit& h : hits) {
    REQUIRE(view.findEntry(h.in, h.out) != nullptr);
    CHECK(std::equal(view.findEntry(h.in, h.out), view.findEntry(h.in, h.out) + view.entryStride(),
                     built.findEntry(h.in, h.out)));
  }
  // Checked like a file's slots: a wrong entry count is refused.
  CHECK_THROWS_AS(LatticeHashTable::inPlace(built.precision(), flash, built.capacity(), built.entryCount() + 1),
                  Error);
}
