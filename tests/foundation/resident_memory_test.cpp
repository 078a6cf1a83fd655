// The resident-memory reader behind --memory-budget.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>

#include "foundation/error.hpp"
#include "foundation/system/resident_memory.hpp"

using lattice::ErrorKind;
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
