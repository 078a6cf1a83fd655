// The compressed LHT (lht/table/compressed_table.hpp): exact membership over the
// whole pair space, payload bytes identical to the hashed table's, and its
// .lht version 3 with the bounded reader's checks.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "foundation/system/atomic_file.hpp"
#include "foundation/error.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/file/lht_file.hpp"
#include "lht/leaf/table_lookup.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

struct Raster {
  LatticeBox box;
  RasterResult result;
};

Raster rasterizeShape(const LatticeObject& object, double oversample) {
  Raster r{LatticeBox(object.bounds, 1.0, oversample), {}};
  RasterOptions options;
  options.progress = false;
  r.result = rasterize(r.box, *object.primitive, options);
  return r;
}

LhtFile fileOf(const Raster& r, LhtForm form, LhtPrecision precision) {
  LhtFile lht;
  lht.box = r.box;
  lht.pairs = r.result.stats.pairs;
  lht.hits = r.result.stats.hits;
  lht.objectHash = 42;
  if (form == LhtForm::Compressed)
    lht.table = CompressedTable(r.result.hits, r.box.cells(), precision);
  else
    lht.table = LatticeHashTable(r.result.hits, precision);
  return lht;
}

// Every ordered pair of grid points of the box (surface or not, and one
// beyond the box) gives the same payload bytes, or none, in both forms.
void checkSameAnswers(const LhtFile& hashed, const LhtFile& compressed) {
  const LhtLookup a(hashed), b(compressed);
  const std::size_t payload = payloadBytes(hashed.precision());
  const BoundaryIndex index(hashed.box.cells());
  std::uint64_t hits = 0, mismatches = 0;
  for (std::uint32_t i = 0; i < index.count(); ++i)
    for (std::uint32_t o = 0; o < index.count(); ++o) {
      const LatticePoint in = index.pointAt(i), out = index.pointAt(o);
      const std::uint8_t* x = a.payload(in, out);
      const std::uint8_t* y = b.payload(in, out);
      if (bool(x) != bool(y) || (x && std::memcmp(x, y, payload) != 0)) ++mismatches;
      if (x) ++hits;
    }
  CHECK(mismatches == 0);
  CHECK(hits == hashed.entryCount());
  // Off the surface: no entry in either form.
  const auto& c = hashed.box.cells();
  const LatticePoint inside{std::uint8_t(c[0] / 2), std::uint8_t(c[1] / 2), std::uint8_t(c[2] / 2)};
  const LatticePoint beyond{std::uint8_t(c[0] + 1), 0, 0};
  if (!hashed.box.onBoundary(inside)) CHECK(b.payload(inside, index.pointAt(0)) == nullptr);
  CHECK(b.payload(beyond, index.pointAt(1)) == nullptr);
  CHECK(b.payload(index.pointAt(0), index.pointAt(0)) == nullptr);
}

}  // namespace

TEST_CASE("compressed LHT: the same payload for every pair, and no entry where the hashed table has none") {
  const std::vector<std::pair<LatticeObject, double>> shapes = {
      {sphereObject(0.5), 1.0}, {sphereObject(0.5), 3.0}, {capsuleObject(0.5, 10.0), 2.0}};
  for (const auto& [object, oversample] : shapes) {
    const Raster r = rasterizeShape(object, oversample);
    for (const LhtPrecisionInfo& p : kLhtPrecisions) {
      INFO(p.name << ", f_lat " << oversample << ", cells " << r.box.cells()[2]);
      const LhtFile hashed = fileOf(r, LhtForm::Hashed, p.precision);
      const LhtFile compressed = fileOf(r, LhtForm::Compressed, p.precision);
      // The rasterizer's hits are symmetric, so each bit stands for both directions.
      CHECK(compressed.compressed().layout() == PairLayout::Symmetric);
      CHECK(compressed.compressed().entryCount() == hashed.hashed().entryCount());
      CHECK(compressed.compressed().payloads().size() == hashed.hashed().entryCount() * payloadBytes(p.precision));
      CHECK(compressed.tableBytes() < hashed.tableBytes());
      checkSameAnswers(hashed, compressed);
    }
  }
}

TEST_CASE("compressed LHT: a hit list that is not symmetric gets the ordered layout, still exact") {
  const Raster r = rasterizeShape(sphereObject(0.5), 2.0);
  Raster lopsided = r;
  // Drop every hit whose entry point comes after its exit point in the numbering.
  const BoundaryIndex index(r.box.cells());
  std::vector<RasterHit> kept = r.result.hits.flat();
  std::erase_if(kept, [&](const RasterHit& h) { return index.indexOf(h.in) > index.indexOf(h.out); });
  lopsided.result.hits = RasterHits(std::move(kept));
  REQUIRE(lopsided.result.hits.size() < r.result.hits.size());
  const LhtFile hashed = fileOf(lopsided, LhtForm::Hashed, LhtPrecision::Thesis);
  const LhtFile compressed = fileOf(lopsided, LhtForm::Compressed, LhtPrecision::Thesis);
  CHECK(compressed.compressed().layout() == PairLayout::Ordered);
  checkSameAnswers(hashed, compressed);
  // And it survives the file.
  const LhtFile back = parseLht(serializeLht(compressed), "ordered.lht");
  CHECK(back.compressed().layout() == PairLayout::Ordered);
  checkSameAnswers(hashed, back);
}

TEST_CASE("compressed LHT: a table read from its body holds those bytes, not a copy of them") {
  const Raster r = rasterizeShape(capsuleObject(0.5, 10.0), 1.0);
  const LhtFile file = fileOf(r, LhtForm::Compressed, LhtPrecision::Thesis);
  const CompressedTable& built = file.compressed();
  std::vector<std::uint8_t> body;
  built.appendBody(body);
  const std::uint8_t* bytes = body.data();
  const CompressedTable read = CompressedTable::fromBody(built.bodyHeader(), std::move(body));
  // The payloads sit where the body put them, after the bitmap's words.
  CHECK(read.payloads().data() == bytes + built.bitmapBytes());
  CHECK(read.bytes() == built.bytes());
  CHECK(read.words() == built.words());
  CHECK(std::ranges::equal(read.payloads(), built.payloads()));
}

TEST_CASE("compressed LHT: version-3 files round-trip, version 2 is refused") {
  const Raster r = rasterizeShape(capsuleObject(0.5, 10.0), 1.0);
  for (const LhtPrecisionInfo& p : kLhtPrecisions) {
    const LhtFile compressed = fileOf(r, LhtForm::Compressed, p.precision);
    const std::vector<std::uint8_t> bytes = serializeLht(compressed);
    CHECK(bytes[8] == kLhtCompressedVersion);
    CHECK(bytes.size() == kLhtHeaderBytesV3 + compressed.compressed().bitmapBytes() +
                               compressed.compressed().payloads().size() + 8);
    const LhtFile back = parseLht(bytes, "c.lht", 42, p.precision, LhtForm::Compressed);
    CHECK(back.version == kLhtCompressedVersion);
    CHECK(back.form() == LhtForm::Compressed);
    CHECK(back.compressed().words() == compressed.compressed().words());
    CHECK(std::ranges::equal(back.compressed().payloads(), compressed.compressed().payloads()));
    CHECK(back.hits == compressed.hits);
    const lattice::testing::TempDir dir("lht-v3");
    writeLhtFile(dir / "c.lht", compressed);
    const LhtFile streamed = readLhtFile(dir / "c.lht", 42, p.precision, LhtForm::Compressed);
    CHECK(std::ranges::equal(streamed.compressed().payloads(), compressed.compressed().payloads()));
    // Asked for the other form: refused, saying which.
    try {
      parseLht(bytes, "c.lht", 42, p.precision, LhtForm::Hashed);
      FAIL("a compressed table was accepted for a hashed one");
    } catch (const Error& e) {
      CHECK(std::string(e.what()).find("holds a compressed table but a hashed one") != std::string::npos);
    }
  }
  // The hashed form is written as version 4 (open addressing).
  CHECK(serializeLht(fileOf(r, LhtForm::Hashed, LhtPrecision::Thesis))[8] == kLhtVersion);
  // A version-2 file written by the program before the compressed form
  // existed (main at 3f4c28b: `lattice rasterize --shape sphere --precision
  // compact`): the chained table, no longer read; a cache of one is rebuilt.
  const std::filesystem::path old = std::filesystem::path(LATTICE_SOURCE_DIR) / "tests/lht/data/sphere-f1-compact-v2.lht";
  CHECK(retiredLhtVersion(old) == 2u);
  try {
    readLhtFile(old);
    FAIL("a version-2 file was read");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("older Lattice (.lht version 2") != std::string::npos);
  }
}

namespace {

std::vector<std::uint8_t> resealed(std::vector<std::uint8_t> bytes) {
  bytes.resize(bytes.size() - 8);
  const std::uint64_t sum = fnv1a64(bytes);
  for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<std::uint8_t>(sum >> (8 * b)));
  return bytes;
}

void put64(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t v) {
  for (int b = 0; b < 8; ++b) bytes[at + b] = static_cast<std::uint8_t>(v >> (8 * b));
}

std::string refusal(const std::vector<std::uint8_t>& bytes) {
  try {
    parseLht(bytes, "bad.lht");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK(std::string(e.what()).find("lattice rasterize") != std::string::npos);
    return e.what();
  }
  FAIL("a bad version-3 file was accepted");
  return {};
}

}  // namespace

TEST_CASE("compressed LHT: bad version-3 files are refused, every count checked against the size first") {
  const Raster r = rasterizeShape(sphereObject(0.5), 2.0);
  const std::vector<std::uint8_t> good = serializeLht(fileOf(r, LhtForm::Compressed, LhtPrecision::Thesis));
  REQUIRE_NOTHROW(parseLht(good, "good.lht"));
  SECTION("truncated inside the header, the bitmap, the payloads") {
    for (std::size_t keep : {kLhtHeaderBytes + 4, kLhtHeaderBytesV3 + 3, kLhtHeaderBytesV3 + 40, good.size() - 9})
      CHECK(refusal(std::vector<std::uint8_t>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(keep)))
                .find("truncated") != std::string::npos);
  }
  SECTION("huge counts are refused before anything is allocated") {
    std::vector<std::uint8_t> bad = good;
    put64(bad, 84, std::uint64_t(1) << 60);  // entries
    CHECK(refusal(resealed(bad)).find("truncated or padded") != std::string::npos);
    bad = good;
    put64(bad, 100, std::uint64_t(1) << 61);  // bitmap words
    CHECK(refusal(resealed(bad)).find("pair space has") != std::string::npos);
  }
  SECTION("cells whose pair space is too large for the form") {
    std::vector<std::uint8_t> bad = good;
    for (int a = 0; a < 3; ++a) bad[12 + 2 * a] = 255;
    CHECK(refusal(resealed(bad)).find("above the compressed form's") != std::string::npos);
    bad = good;
    bad[12] = 0;
    CHECK(refusal(resealed(bad)).find("outside 1..255") != std::string::npos);
  }
  SECTION("unknown form and layout codes") {
    std::vector<std::uint8_t> bad = good;
    bad[108] = 9;
    CHECK(refusal(resealed(bad)).find("form code 9") != std::string::npos);
    bad = good;
    bad[110] = 5;
    CHECK(refusal(resealed(bad)).find("layout code 5") != std::string::npos);
  }
  SECTION("a bitmap that disagrees with the entry count, or sets bits past the pair space") {
    std::vector<std::uint8_t> bad = good;
    bad[kLhtHeaderBytesV3] ^= 0x01;  // one pair more or less: two entries more or less
    CHECK(refusal(resealed(bad)).find("inconsistent") != std::string::npos);
    bad = good;
    const std::size_t lastWord = kLhtHeaderBytesV3 + 8 * (fileOf(r, LhtForm::Compressed, LhtPrecision::Thesis)
                                                              .compressed().words().size() - 1);
    bad[lastWord + 7] |= 0x80;
    CHECK(refusal(resealed(bad)).find("inconsistent") != std::string::npos);
  }
  SECTION("a flipped byte fails the checksum") {
    std::vector<std::uint8_t> bad = good;
    bad[good.size() - 12] ^= 0x04;
    CHECK(refusal(bad).find("checksum") != std::string::npos);
  }
}
