// README.md's "Quick tour" runs top to bottom on a fresh directory:
// its commands are read from the README itself, so the tour cannot
// drift from the program. Only the scenes are copied in; everything else a
// command needs must come from a command before it. A command that needs a
// real terminal (`--port auto`) is skipped, saying so.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The lines of the first ```sh block after the "## Quick tour" heading.
std::vector<std::string> tourLines() {
  const std::string readme = readFile(std::filesystem::path(LATTICE_SOURCE_DIR) / "README.md");
  const std::size_t heading = readme.find("## Quick tour");
  if (heading == std::string::npos) return {};
  const std::size_t open = readme.find("```sh\n", heading);
  const std::size_t close = readme.find("\n```", open + 6);
  if (open == std::string::npos || close == std::string::npos) return {};
  std::istringstream block(readme.substr(open + 6, close - open - 6));
  std::vector<std::string> lines;
  for (std::string line; std::getline(block, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

TEST_CASE("README's Quick tour runs top to bottom in a fresh directory", "[tour]") {
  const std::vector<std::string> lines = tourLines();
  REQUIRE(lines.size() >= 8);
  // The tour names the binary as built; here it is the build tree's.
  REQUIRE(lines.front().rfind("L=", 0) == 0);
  const lattice::testing::TempDir scratch("quick-tour");
  std::filesystem::copy(std::filesystem::path(LATTICE_SOURCE_DIR) / "scenes", scratch.path() / "scenes",
                        std::filesystem::copy_options::recursive);
  std::string script = "set -euo pipefail\n";
  script += fmt::format("L='{}'\n", lattice::testing::latticeBinary().string());
  int run = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.find("--port auto") != std::string::npos) {
      WARN("skipped (needs a real terminal on a USB-serial adapter): " << line);
      continue;
    }
    // Each command announced, so a failure names its line.
    script += fmt::format("echo '>>> {}' >&2\n{}\n", std::to_string(i), line);
    ++run;
  }
  CHECK(run >= 8);
  const std::string scriptFile = scratch / "tour.sh";
  std::ofstream(scriptFile) << script;
  const std::string log = scratch / "tour.log";
  const int status = std::system(fmt::format("cd '{}' && bash tour.sh >'{}' 2>&1 </dev/null",
                                             scratch.path().string(), log).c_str());
  INFO("tour script:\n" << script << "\noutput:\n" << readFile(log));
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  // What the tour says it makes, it made.
  for (const char* made : {"torus.png", "exact.png", "lattice.png", "diff.png", "screen.png", "terminal.png"})
    CHECK(std::filesystem::exists(scratch.path() / made));
}
