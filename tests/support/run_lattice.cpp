#include "tests/support/run_lattice.hpp"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace lattice::testing {

std::filesystem::path latticeBinary() {
  if (const char* exe = std::getenv("LATTICE_EXE"); exe != nullptr && *exe != '\0') return exe;
  return std::filesystem::path(LATTICE_BINARY_DIR) / "app" / "lattice";
}

CommandRun runLattice(const std::string& arguments) {
  static std::atomic<unsigned> counter{0};
  const auto errFile = std::filesystem::temp_directory_path() /
                       fmt::format("lattice-test-{}-{}.err", ::getpid(), counter.fetch_add(1));
  const int status = std::system(
      fmt::format("'{}' {} 2>'{}' </dev/null", latticeBinary().string(), arguments, errFile.string()).c_str());
  CommandRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(errFile);
  std::stringstream text;
  text << in.rdbuf();
  run.stderrText = text.str();
  std::filesystem::remove(errFile);
  return run;
}

}  // namespace lattice::testing
