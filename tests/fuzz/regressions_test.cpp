// Every input that ever made a fuzzer fail (fuzz/regressions/<target>/) goes
// back through the same entry function the harness calls (fuzz/entries.hpp),
// in every build: g++ Release here, clang ASan + UBSan in build-asan/. An
// input passes when the entry returns; lattice::Error is swallowed inside
// it, anything else escaping (or a crash, or a sanitizer report) fails.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

#include "fuzz/entries.hpp"

namespace {

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::filesystem::path kRegressions = std::filesystem::path(LATTICE_SOURCE_DIR) / "fuzz" / "regressions";

}  // namespace

TEST_CASE("every regression input replays through its target without a crash") {
  std::size_t replayed = 0;
  for (const auto& target : lattice::fuzz::targets()) {
    const auto folder = kRegressions / target.name;
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& file : std::filesystem::directory_iterator(folder)) {
      if (!file.is_regular_file() || file.path().filename() == "README.md") continue;
      const auto bytes = readBytes(file.path());
      INFO("fuzz/regressions/" << target.name << "/" << file.path().filename().string() << " (" << bytes.size()
                               << " bytes)");
      CHECK_NOTHROW(target.entry(bytes));
      ++replayed;
    }
  }
  // The folder is not allowed to go missing or empty unnoticed.
  CHECK(replayed > 0);
}

TEST_CASE("regression folders are named after known targets") {
  std::set<std::string> known;
  for (const auto& target : lattice::fuzz::targets()) known.insert(std::string(target.name));
  REQUIRE(std::filesystem::is_directory(kRegressions));
  for (const auto& entry : std::filesystem::directory_iterator(kRegressions)) {
    if (!entry.is_directory()) continue;
    INFO("fuzz/regressions/" << entry.path().filename().string());
    CHECK(known.count(entry.path().filename().string()) == 1);
  }
}
