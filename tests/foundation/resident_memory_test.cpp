// The resident-memory reader and the size parser behind --memory-budget.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>

#include "foundation/error.hpp"
#include "foundation/system/resident_memory.hpp"

using lattice::ErrorKind;
using lattice::formatBytes;
using lattice::parseByteCount;
using lattice::parseProcStatus;

TEST_CASE("util:proc_status_fields_parse_in_bytes") {
  const char* status =
      "Name:\tlattice\nVmPeak:\t   20000 kB\nVmHWM:\t    8212 kB\nVmRSS:\t    7000 kB\nThreads:\t1\n";
  const auto m = parseProcStatus(status);
  REQUIRE(m);
  CHECK(m->peak == 8212u * 1024);
  CHECK(m->current == 7000u * 1024);
  CHECK_FALSE(parseProcStatus("VmRSS:\t 10 kB\n"));              // no VmHWM
  CHECK_FALSE(parseProcStatus("VmHWM: x kB\nVmRSS: 10 kB\n"));   // not a number
  CHECK_FALSE(parseProcStatus("VmHWMx: 5 kB\nVmRSS: 10 kB\n"));  // a longer name is another field
}

TEST_CASE("util:resident_memory_follows_touched_pages") {
  const auto before = lattice::residentMemory();
  REQUIRE(before);
  CHECK(before->current > 0);
  CHECK(before->peak >= before->current);
  // 32 MiB written page by page must show up as resident.
  constexpr std::size_t kBytes = 32u << 20;
  auto block = std::make_unique<char[]>(kBytes);
  std::memset(block.get(), 1, kBytes);
  const auto after = lattice::residentMemory();
  REQUIRE(after);
  CHECK(after->current >= before->current + kBytes - (1u << 20));
  CHECK(after->peak >= after->current);
  CHECK(block[kBytes - 1] == 1);
}

TEST_CASE("util:byte_counts_take_binary_suffixes") {
  CHECK(parseByteCount("8388608", "--x") == 8388608u);
  CHECK(parseByteCount("8192K", "--x") == 8388608u);
  CHECK(parseByteCount("8KiB", "--x") == 8192u);
  CHECK(parseByteCount("8MiB", "--x") == 8388608u);
  CHECK(parseByteCount("8mb", "--x") == 8388608u);
  CHECK(parseByteCount("1.5M", "--x") == 1572864u);
  CHECK(parseByteCount("2G", "--x") == 2147483648u);
  for (const char* bad : {"", "0", "-1", "8XB", "M", "8 M", "nan", "1e30"}) {
    INFO(bad);
    try {
      parseByteCount(bad, "--memory-budget");
      FAIL("accepted");
    } catch (const lattice::Error& e) {
      CHECK(e.kind() == ErrorKind::Usage);
      CHECK_THAT(e.what(), Catch::Contains("--memory-budget") && Catch::Contains("8MiB"));
    }
  }
}

TEST_CASE("util:byte_counts_format_readably") {
  CHECK(formatBytes(512) == "512 B");
  CHECK(formatBytes(4000) == "3.9 KiB");
  CHECK(formatBytes(8650752) == "8.25 MiB");
}
