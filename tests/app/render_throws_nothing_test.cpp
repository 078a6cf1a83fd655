// A render that succeeds throws no exception on its way (building the command
// tree, checking the outputs, loading, rendering): in the static build the
// first exception thrown makes the unwinder read all of .eh_frame and keep a
// sorted index of it on the heap, about 440 KiB more resident for Plate 7
// (docs/memory.md, "Code pages"). Method: the real binary under gdb with a
// catchpoint on every throw, its stream written over an existing file (the
// output check then takes its longest path); skips with a warning where gdb
// is missing.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using lattice::testing::latticeBinary;
using lattice::testing::TempDir;

std::string runAndRead(const std::string& command) {
  std::string text;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    ::pclose(pipe);
  }
  return text;
}

}  // namespace

TEST_CASE("a render to a stream and a PNG throws no exception", "[render][memory]") {
  if (std::system("command -v gdb >/dev/null 2>&1") != 0) {
    WARN("skipped: gdb is missing (apt-get install gdb)");
    return;
  }
  const TempDir scratch("throws-nothing");
  std::ofstream(scratch.path() / "old.tek") << "replaced";
  const std::string render =
      fmt::format("render '{}/scenes/hook.toml' --width 32 --height 32 --device tek4125 --stream '{}' -o '{}' --quiet",
                  LATTICE_SOURCE_DIR, (scratch.path() / "old.tek").string(), (scratch.path() / "screen.png").string());
  const std::string log = runAndRead(
      // LeakSanitizer cannot run under ptrace and would end the sanitizer build's run with an error.
      fmt::format("ASAN_OPTIONS=\"${{ASAN_OPTIONS:+$ASAN_OPTIONS:}}detect_leaks=0\" "
                  "gdb -nx -batch -ex 'catch throw' -ex run -ex 'bt 6' --args '{}' {} 2>&1 </dev/null",
                  latticeBinary().string(), render));
  INFO(log);
  REQUIRE(log.find("Catchpoint 1 (throw)") != std::string::npos);  // the catchpoint was set
  CHECK(log.find("exception thrown") == std::string::npos);
  CHECK(log.find("exited normally") != std::string::npos);
}
