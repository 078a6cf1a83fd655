// Sizes as people type them (foundation/byte_count.hpp): the one parser
// behind --memory-budget, --lht-cache, --wire-bytes and every Bytes setting.
#include <catch2/catch.hpp>

#include <string>

#include "foundation/byte_count.hpp"
#include "foundation/error.hpp"

using lattice::ErrorKind;
using lattice::formatBytes;
using lattice::parseByteCount;

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

TEST_CASE("util:byte_count_text_reads_back_exactly") {
  CHECK(lattice::byteCountText(std::uint64_t(64) << 20) == "64MiB");
  CHECK(lattice::byteCountText(57344) == "56KiB");
  CHECK(lattice::byteCountText(57600) == "57600");
  CHECK(lattice::byteCountText(std::uint64_t(3) << 30) == "3GiB");
  for (std::uint64_t n : {std::uint64_t(1), std::uint64_t(1023), std::uint64_t(1025), std::uint64_t(9) << 40})
    CHECK(parseByteCount(lattice::byteCountText(n), "--x") == n);
  CHECK(lattice::byteCountProblem("8MiB").empty());
  CHECK(lattice::byteCountProblem("nan").find("'nan' is not a size in bytes") != std::string::npos);
}
