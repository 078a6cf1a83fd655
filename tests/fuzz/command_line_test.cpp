// The command-line fuzzing entry in every build (g++ here, ASan + UBSan in
// build-asan/): a few hundred programs from a fixed seed, so a flag parser,
// --at, the wire budget or show that crashes, hangs or throws anything but
// an exit code fails the ordinary suite too, before any fuzzer runs.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "fuzz/entries.hpp"

TEST_CASE("the command line answers random programs with exit codes only", "[fuzz][cli]") {
  // Outputs stay in the entry's scratch directory: none appear here.
  const auto here = [] {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::current_path()))
      names.insert(entry.path().filename().string());
    return names;
  };
  const std::set<std::string> before = here();
  std::mt19937 random(20261204);
  for (int run = 0; run < 400; ++run) {
    std::vector<std::uint8_t> program(4 + random() % 40);
    for (std::uint8_t& byte : program) byte = static_cast<std::uint8_t>(random() % 255);  // no 0xFF: all argv
    program.push_back(0xFF);
    for (int i = 0; i < 64; ++i) program.push_back(static_cast<std::uint8_t>(random()));
    INFO("run " << run);
    CHECK_NOTHROW(lattice::fuzz::commandLine(program));
  }
  CHECK(here() == before);
}
