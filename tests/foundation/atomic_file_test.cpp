#include <catch2/catch.hpp>

#include <filesystem>

#include "foundation/system/atomic_file.hpp"
#include "tests/support/temp_dir.hpp"
#include "foundation/error.hpp"

using namespace lattice;
namespace fs = std::filesystem;

namespace {
std::size_t filesIn(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}
}  // namespace

TEST_CASE("an atomic file appears only when closed, with all its bytes") {
  const lattice::testing::TempDir scratch("atomic");
  const fs::path dir = scratch.path();
  fs::path target = dir / "out.bin";
  fs::remove(target);
  std::vector<std::uint8_t> payload(200000);
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i * 7 + 3);
  {
    AtomicFile file(target);
    file.write(std::span<const std::uint8_t>(payload).first(100000));
    file.write(std::span<const std::uint8_t>(payload).subspan(100000));
    CHECK_FALSE(fs::exists(target));
    CHECK(file.bytesWritten() == payload.size());
    file.close();
  }
  CHECK(readWholeFile(target) == payload);
  CHECK(filesIn(dir) == 1);  // no temporary left behind
}

TEST_CASE("an atomic file abandoned before close leaves the old file untouched") {
  const lattice::testing::TempDir scratch("atomic");
  const fs::path dir = scratch.path();
  fs::path target = dir / "keep.txt";
  writeFileAtomically(target, std::vector<std::uint8_t>{'o', 'l', 'd'});
  {
    AtomicFile file(target);
    file.write(std::string_view("new contents that never land"));
  }  // destroyed without close(): e.g. an exception while rendering
  CHECK(readWholeFile(target) == std::vector<std::uint8_t>{'o', 'l', 'd'});
  CHECK(filesIn(dir) == 1);
}

TEST_CASE("atomic file errors name the path") {
  try {
    AtomicFile file("/nonexistent-dir-for-lattice/out.png");
    FAIL("opening in a missing directory must throw");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Output);
    CHECK(std::string(e.what()).find("/nonexistent-dir-for-lattice/out.png") != std::string::npos);
  }
  try {
    readWholeFile("/nonexistent-dir-for-lattice/in.bin");
    FAIL("reading a missing file must throw");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK(std::string(e.what()).find("in.bin") != std::string::npos);
  }
}

TEST_CASE("readFileUpTo refuses a file over its limit before reading it, and an endless one at the limit") {
  const lattice::testing::TempDir scratch("read-up-to");
  const fs::path small = scratch.path() / "small.bin";
  writeFileAtomically(small, std::vector<std::uint8_t>(1000, 7));
  CHECK(readFileUpTo(small, 1000, "a test file").size() == 1000);
  CHECK_THROWS_WITH(readFileUpTo(small, 999, "a test file"),
                    Catch::Contains("small.bin: 1000 bytes, more than the 999-byte limit for a test file"));
  CHECK_THROWS_WITH(readFileUpTo("/dev/zero", 4096, "a test file"),
                    Catch::Contains("/dev/zero: more than the 4096-byte limit"));
}
