// A command's outputs land together or not at all
// (foundation/system/output_transaction.hpp).
#include <catch2/catch.hpp>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "foundation/error.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/system/output_transaction.hpp"
#include "foundation/system/temp_file_registry.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

void put(const std::string& path, const std::string& text, lattice::AtomicFile::Landing landing =
                                                                lattice::AtomicFile::Landing::WithCommand) {
  lattice::writeFileAtomically(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
                               landing);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t filesIn(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

}  // namespace

TEST_CASE("outputs closed inside a transaction appear only at commit", "[output]") {
  const lattice::testing::TempDir dir("transaction-commit");
  const std::size_t liveBefore = lattice::TempFileRegistry::live();
  {
    lattice::OutputTransaction outputs;
    put(dir / "a.tek", "stream");
    put(dir / "b.png", "picture");
    CHECK_FALSE(std::filesystem::exists(dir / "a.tek"));
    CHECK_FALSE(std::filesystem::exists(dir / "b.png"));
    CHECK(outputs.pending() == 2);
    // Still registered, so a signal now would unlink the temporaries.
    CHECK(lattice::TempFileRegistry::live() == liveBefore + 2);
    outputs.commit();
  }
  CHECK(slurp(dir / "a.tek") == "stream");
  CHECK(slurp(dir / "b.png") == "picture");
  CHECK(filesIn(dir.path()) == 2);  // no temporary left
  CHECK(lattice::TempFileRegistry::live() == liveBefore);
}

TEST_CASE("a transaction left without commit leaves old files untouched and no temporaries", "[output]") {
  const lattice::testing::TempDir dir("transaction-abort");
  put(dir / "a.tek", "old stream");
  const std::size_t liveBefore = lattice::TempFileRegistry::live();
  try {
    lattice::OutputTransaction outputs;
    put(dir / "a.tek", "new stream");
    put(dir / "b.png", "new picture");
    throw lattice::Error(lattice::ErrorKind::Output, "the disk filled");
  } catch (const lattice::Error&) {
  }
  CHECK(slurp(dir / "a.tek") == "old stream");
  CHECK_FALSE(std::filesystem::exists(dir / "b.png"));
  CHECK(filesIn(dir.path()) == 1);
  CHECK(lattice::TempFileRegistry::live() == liveBefore);
}

TEST_CASE("a cache written with Landing::Now lands at once, inside a transaction too", "[output]") {
  const lattice::testing::TempDir dir("transaction-now");
  {
    lattice::OutputTransaction outputs;
    put(dir / "hair.lht", "table", lattice::AtomicFile::Landing::Now);
    CHECK(slurp(dir / "hair.lht") == "table");
    CHECK(outputs.pending() == 0);
  }
  CHECK(slurp(dir / "hair.lht") == "table");
}

TEST_CASE("without a transaction a file lands when closed, as before", "[output]") {
  const lattice::testing::TempDir dir("transaction-none");
  put(dir / "x.png", "x");
  CHECK(slurp(dir / "x.png") == "x");
}
