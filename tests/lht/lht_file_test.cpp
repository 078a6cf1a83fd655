#include <catch2/catch.hpp>
#include <fmt/core.h>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>

#include "foundation/system/atomic_file.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/file/lht_file.hpp"
#include "tests/support/temp_dir.hpp"
#include "foundation/error.hpp"
#include "foundation/system/resident_memory.hpp"

using namespace lattice;
using namespace lattice::lht;

namespace {

LhtFile makeSphereLht(LhtPrecision precision = LhtPrecision::Thesis, LhtForm form = LhtForm::Hashed) {
  const LatticeObject sphere = sphereObject(0.5);
  LhtFile lht;
  lht.box = LatticeBox(sphere.bounds, 1.0, 2.0);
  RasterOptions options;
  options.progress = false;
  const RasterResult raster = rasterize(lht.box, *sphere.primitive, options);
  lht.objectHash = sphere.hash();
  lht.pairs = raster.stats.pairs;
  lht.hits = raster.stats.hits;
  if (form == LhtForm::Compressed)
    lht.table = CompressedTable(raster.hits, lht.box.cells(), precision);
  else
    lht.table = LatticeHashTable(raster.hits, precision);
  return lht;
}

// Replaces the trailing checksum so a deliberately changed file passes it.
std::vector<std::uint8_t> resealed(std::vector<std::uint8_t> bytes) {
  bytes.resize(bytes.size() - 8);
  const std::uint64_t sum = fnv1a64(bytes);
  for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<std::uint8_t>(sum >> (8 * b)));
  return bytes;
}

// The file an older Lattice wrote: `version` 1 or 2 in a version-4 file's
// header, or version 3 with the hashed form code. The body is not the old
// chained layout: the header alone decides, before any body is read.
std::vector<std::uint8_t> olderFile(const LhtFile& lht, std::uint32_t version) {
  std::vector<std::uint8_t> bytes = serializeLht(lht);
  bytes[8] = static_cast<std::uint8_t>(version);
  if (version == kLhtCompressedVersion) bytes.insert(bytes.begin() + kLhtHeaderBytes, 8, 0);  // form code 0: hashed
  return resealed(bytes);
}

// The message of the Error thrown by parsing `bytes`, which must be Input.
std::string refusal(const std::vector<std::uint8_t>& bytes, std::optional<std::uint64_t> hash = std::nullopt,
                    std::optional<LhtPrecision> precision = std::nullopt) {
  try {
    parseLht(bytes, "bad.lht", hash, precision);
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    return e.what();
  }
  FAIL("a bad .lht file was accepted");
  return {};
}

}  // namespace

TEST_CASE("lht file: FNV-1a 64 matches the published test vectors") {
  CHECK(fnv1a64("") == 0xcbf29ce484222325ull);
  CHECK(fnv1a64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a64("foobar") == 0x85944171f73967e8ull);
}

TEST_CASE("lht file: every precision writes and reads back the identical table and header") {
  for (const LhtPrecisionInfo& form : kLhtPrecisions) {
    INFO(form.name);
    const LhtFile lht = makeSphereLht(form.precision);
    const auto dir = std::filesystem::temp_directory_path() / ("lattice-lht-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / "sphere.lht";
    writeLhtFile(path, lht);
    const LhtFile back = readLhtFile(path, lht.objectHash, form.precision);
    std::filesystem::remove_all(dir);
    CHECK(back.version == kLhtVersion);
    CHECK(back.precision() == form.precision);
    CHECK(back.box.cells() == lht.box.cells());
    CHECK(back.box.lambda() == lht.box.lambda());
    CHECK(back.box.oversample() == lht.box.oversample());
    CHECK(back.box.origin() == lht.box.origin());
    CHECK(back.pairs == 18750);
    CHECK(back.hits == 3486);
    CHECK(back.hashed().entryCount() == lht.hashed().entryCount());
    CHECK(back.hashed().capacity() == lht.hashed().capacity());
    CHECK(back.hashed().slotBytes() == lht.hashed().slotBytes());
    CHECK(serializeLht(back) == serializeLht(lht));
    const std::vector<std::uint8_t> bytes = serializeLht(lht);
    CHECK(bytes.size() == kLhtHeaderBytes + lht.hashed().capacity() * (form.entryBytes - 4) + 8);
    CHECK(bytes[8] == 4);                                           // version 4: open addressing
    CHECK(bytes[18] == static_cast<std::uint8_t>(form.precision));  // the precision code, u16 LE
    CHECK(bytes[19] == 0);
  }
}

TEST_CASE("lht file: the chained tables of versions 1 to 3 are refused, and a cache of one is told apart") {
  const LhtFile lht = makeSphereLht();
  const lattice::testing::TempDir dir("lht-older");
  for (std::uint32_t version : {1u, 2u, kLhtCompressedVersion}) {
    INFO("version " << version);
    const std::vector<std::uint8_t> old = olderFile(lht, version);
    const std::string message = refusal(old);
    CHECK(message.find(fmt::format("older Lattice (.lht version {}", version)) != std::string::npos);
    CHECK(message.find("lattice rasterize") != std::string::npos);
    const std::string path = dir / fmt::format("v{}.lht", version);
    writeFileAtomically(path, old);
    CHECK(retiredLhtVersion(path) == version);
  }
  // Today's files, and a file that is not an .lht at all, are not old caches.
  writeLhtFile(dir / "v4.lht", lht, AtomicFile::Landing::Now);
  CHECK_FALSE(retiredLhtVersion(dir / "v4.lht"));
  writeLhtFile(dir / "v3.lht", makeSphereLht(LhtPrecision::Thesis, LhtForm::Compressed), AtomicFile::Landing::Now);
  CHECK_FALSE(retiredLhtVersion(dir / "v3.lht"));
  writeFileAtomically(dir / "junk.lht", std::vector<std::uint8_t>(200, 2));
  CHECK_FALSE(retiredLhtVersion(dir / "junk.lht"));
  CHECK_FALSE(retiredLhtVersion(dir / "missing.lht"));
}

TEST_CASE("lht file: every kind of bad file is refused with a message naming it and the fix") {
  const LhtFile lht = makeSphereLht();
  const std::vector<std::uint8_t> good = serializeLht(lht);
  REQUIRE_NOTHROW(parseLht(good, "good.lht", lht.objectHash));

  SECTION("truncated") {
    for (std::size_t keep : {std::size_t(0), std::size_t(5), kLhtHeaderBytes - 1, kLhtHeaderBytes + 20, good.size() - 1}) {
      std::vector<std::uint8_t> cut(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(keep));
      const std::string message = refusal(cut);
      CHECK(message.find("bad.lht") != std::string::npos);
      CHECK(message.find("lattice rasterize") != std::string::npos);
    }
    CHECK(refusal(std::vector<std::uint8_t>(good.begin(), good.end() - 3)).find("truncated") != std::string::npos);
  }
  SECTION("a flipped byte anywhere after the magic fails the checksum") {
    for (std::size_t at : {std::size_t(9), std::size_t(70), kLhtHeaderBytes + 3, good.size() - 20, good.size() - 1}) {
      std::vector<std::uint8_t> bad = good;
      bad[at] ^= 0x10;
      INFO("byte " << at);
      const std::string message = refusal(bad);
      const bool explained = message.find("checksum") != std::string::npos ||
                             message.find("version") != std::string::npos ||
                             message.find("truncated") != std::string::npos;
      CHECK(explained);
    }
    std::vector<std::uint8_t> bad = good;
    bad[kLhtHeaderBytes + 3] ^= 0x01;
    CHECK(refusal(bad).find("checksum") != std::string::npos);
  }
  SECTION("wrong magic") {
    std::vector<std::uint8_t> bad = good;
    bad[0] = 'X';
    CHECK(refusal(bad).find("magic") != std::string::npos);
    const std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    CHECK(refusal(png).find("magic") != std::string::npos);
  }
  SECTION("wrong version") {
    std::vector<std::uint8_t> bad = good;
    bad[8] = 5;
    CHECK(refusal(bad).find("version 5") != std::string::npos);
  }
  SECTION("an unknown precision code, even with a valid checksum") {
    std::vector<std::uint8_t> bad = good;
    bad[18] = 7;
    const std::string message = refusal(resealed(bad));
    CHECK(message.find("precision code 7") != std::string::npos);
    CHECK(message.find("0 thesis, 1 wide, 2 compact") != std::string::npos);
    CHECK(message.find("lattice rasterize") != std::string::npos);
  }
  SECTION("another precision than asked for") {
    const std::string message = refusal(good, lht.objectHash, LhtPrecision::Compact);
    CHECK(message.find("bad.lht") != std::string::npos);
    CHECK(message.find("'thesis' entries (14 bytes each)") != std::string::npos);
    CHECK(message.find("'compact'") != std::string::npos);
  }
  SECTION("a precision code that changes the stride is caught as a size mismatch") {
    std::vector<std::uint8_t> bad = good;
    bad[18] = static_cast<std::uint8_t>(LhtPrecision::Wide);
    CHECK(refusal(resealed(bad)).find("truncated or padded") != std::string::npos);
  }
  SECTION("rasterized from another object") {
    const std::string message = refusal(good, sphereObject(0.6).hash());
    CHECK(message.find("different object") != std::string::npos);
  }
  SECTION("a checksum-valid file with inconsistent counts") {
    // Forge: bump the entry count and re-seal the checksum; the chain check catches it.
    std::vector<std::uint8_t> bad = good;
    bad[84] = static_cast<std::uint8_t>(bad[84] + 1);
    CHECK(refusal(resealed(bad)).find("inconsistent") != std::string::npos);
  }
  SECTION("a missing file") {
    CHECK_THROWS_AS(readLhtFile("/nonexistent/dir/x.lht"), Error);
  }
}

TEST_CASE("lht file: the streamed file reader agrees with parseLht on good and bad files") {
  const lattice::testing::TempDir scratch("lht-stream");
  const LhtFile lht = makeSphereLht();
  const std::vector<std::uint8_t> good = serializeLht(lht);
  const std::string path = scratch / "bad.lht";
  writeFileAtomically(path, good);
  const LhtFile back = readLhtFile(path, lht.objectHash);
  CHECK(back.hashed().slotBytes() == lht.hashed().slotBytes());
  CHECK(back.objectHash == lht.objectHash);

  std::vector<std::vector<std::uint8_t>> bad;
  for (std::size_t keep : {std::size_t(0), std::size_t(5), kLhtHeaderBytes - 1, kLhtHeaderBytes + 20, good.size() - 1})
    bad.emplace_back(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(keep));
  for (std::size_t at : {std::size_t(0), std::size_t(9), std::size_t(18), kLhtHeaderBytes + 3, good.size() - 1}) {
    bad.push_back(good);
    bad.back()[at] ^= 0x10;
  }
  bad.push_back(good);
  bad.back().push_back(0);  // padded
  for (const auto& bytes : bad) {
    writeFileAtomically(path, bytes);
    const std::string expected = refusal(bytes);
    try {
      readLhtFile(path);
      FAIL("the file reader accepted a file parseLht refuses");
    } catch (const Error& e) {
      CHECK(e.kind() == ErrorKind::Input);
      // parseLht names the file "bad.lht"; the reader names it by its path.
      CHECK(std::string(e.what()).substr(path.size()) == expected.substr(std::strlen("bad.lht")));
    }
  }
}

TEST_CASE("lht file: a huge junk file is refused from its first bytes, without reading it") {
  // 256 MiB, sparse: reading it whole, as the reader once did, would raise
  // the peak resident memory by as much.
  const lattice::testing::TempDir scratch("lht-junk");
  const std::string path = scratch / "junk.lht";
  const std::uint64_t size = std::uint64_t(256) << 20;
  {
    std::vector<std::uint8_t> start(4096, 0xA5);
    writeFileAtomically(path, start);
    std::filesystem::resize_file(path, size);
  }
  const auto before = lattice::residentMemory();
  try {
    readLhtFile(path);
    FAIL("junk was accepted");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("wrong magic") != std::string::npos);
  }
  // With the right magic and version but a table the header does not
  // describe, the size check refuses it, again before reading the table.
  std::vector<std::uint8_t> header = serializeLht(makeSphereLht());
  header.resize(kLhtHeaderBytes);
  writeFileAtomically(path, header);
  std::filesystem::resize_file(path, size);
  try {
    readLhtFile(path);
    FAIL("a header with the wrong size was accepted");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("truncated or padded: 268435456 bytes") != std::string::npos);
  }
  const auto after = lattice::residentMemory();
  if (before && after) CHECK(after->peak < before->peak + (std::uint64_t(32) << 20));
}
