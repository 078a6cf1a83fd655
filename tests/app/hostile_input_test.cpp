// Whole-program limits (docs/limits.md): an endless stream into
// `lattice emulate` stops at the stream-size limit, and running out of
// memory is an input error (exit 3), never an internal error (exit 70).
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::runLattice;

TEST_CASE("lattice emulate /dev/zero stops at the stream-size limit with exit 3", "[limits]") {
  const lattice::testing::TempDir scratch("emulate-zero");
  for (const char* device : {"tek4125", "tek4027"}) {
    const std::string out = scratch / "zero.png";
    const auto run = runLattice(fmt::format("emulate --device {} --raw /dev/zero -o '{}'", device, out));
    INFO(device << ": " << run.stderrText);
    CHECK(run.exitCode == 3);
    CHECK_THAT(run.stderrText, Catch::Contains("/dev/zero") && Catch::Contains("268435456 bytes") &&
                                   Catch::Contains("kMaxStreamBytes"));
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("running out of memory exits 3 with a message, not 70", "[limits]") {
  // A 9000x9000 truecolour picture needs about 240 MB; the address space is
  // capped at 150 MB, so an allocation fails: std::bad_alloc.
#ifdef LATTICE_SANITIZED
  WARN("skipped under the sanitizers: ASan reserves terabytes of address space for its shadow memory, so no "
       "sanitized binary starts under `ulimit -v`, and its allocator aborts rather than throw (the g++ build runs "
       "it)");
  return;
#endif
  const lattice::testing::TempDir scratch("out-of-memory");
  const std::string err = scratch / "err.txt";
  const int status = std::system(
      fmt::format("ulimit -v 150000; exec '{}' render '{}/scenes/torus-floor.toml' --width 9000 --height 9000 "
                  "--threads 1 -o '{}' 2>'{}'",
                  lattice::testing::latticeBinary().string(), LATTICE_SOURCE_DIR, scratch / "big.png", err)
          .c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 3);
  std::FILE* f = std::fopen(err.c_str(), "r");
  REQUIRE(f != nullptr);
  char text[512] = {};
  const std::size_t n = std::fread(text, 1, sizeof text - 1, f);
  std::fclose(f);
  CHECK_THAT(std::string(text, n), Catch::Contains("out of memory") && !Catch::Contains("internal error"));
}
