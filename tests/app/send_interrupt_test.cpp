// Ctrl-C during `lattice send` (and SIGTERM, SIGHUP): the send stops where it
// is and prints what a stall prints, how many bytes went out of how many and
// the exact `--resume` command, and the process still ends by the signal
// (so the shell's status is 128 + the signal: 130 for Ctrl-C). The real
// binary is run as a child against a virtual 4125 at 1200 baud, where the
// stream takes about a minute, and signalled after a second.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "tests/support/golden.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using Clock = std::chrono::steady_clock;

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Starts `lattice ARGS` with standard error to `errPath`, and the three
// signals at their default action and unblocked, as for a job in the
// foreground of a terminal (a test runner may have started us otherwise).
pid_t startLattice(const std::vector<std::string>& args, const std::string& errPath) {
  const std::string binary = lattice::testing::latticeBinary().string();
  std::vector<std::string> all{binary};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : all) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int in = ::open("/dev/null", O_RDONLY);
    if (err < 0 || in < 0) ::_exit(126);
    ::dup2(err, 2);
    ::dup2(in, 0);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// The child's wait status, or nothing if it has not ended by the deadline
// (it is then killed, so a broken build fails the test instead of hanging it).
std::optional<int> waitUntil(pid_t pid, Clock::time_point deadline) {
  for (;;) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    if (Clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return std::nullopt;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

TEST_CASE("a signal during send prints the bytes sent and the --resume command, then ends by the signal", "[send]") {
  const lattice::testing::TempDir scratch("send-interrupt");
  const std::string stream = scratch / "hole.tek";
  const auto render = lattice::testing::runLattice(
      fmt::format("render '{}' --width 96 --height 72 --device tek4125 --stream '{}' -q",
                  lattice::testing::sourcePath("scenes/sphere-hole.toml").string(), stream));
  REQUIRE(render.exitCode == 0);
  const std::uint64_t total = std::filesystem::file_size(stream);
  REQUIRE(total > 2000);  // well over the ~120 bytes a second at 1200 baud lets out

  const int signal = GENERATE(SIGINT, SIGTERM, SIGHUP);
  INFO("signal " << signal);
  const std::string errPath = scratch / "stderr.txt";
  const std::string screen = scratch / "screen.png";
  const pid_t pid =
      startLattice({"send", stream, "--port", "virtual:tek4125", "--baud", "1200", "-o", screen}, errPath);
  REQUIRE(pid > 0);
  // Under way: the virtual terminal is up, then a second of bytes.
  const Clock::time_point started = Clock::now();
  while (readText(errPath).find("a virtual Tektronix 4125") == std::string::npos &&
         Clock::now() < started + std::chrono::seconds(20))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const Clock::time_point signalled = Clock::now();
  ::kill(pid, signal);
  const std::optional<int> status = waitUntil(pid, signalled + std::chrono::seconds(20));
  const double seconds = std::chrono::duration<double>(Clock::now() - signalled).count();
  const std::string err = readText(errPath);
  INFO(err);
  REQUIRE(status.has_value());
  // Ended by the signal itself, as without the handler: what the shell
  // reports as 128 + the signal, 130 for SIGINT.
  REQUIRE(WIFSIGNALED(*status));
  CHECK(WTERMSIG(*status) == signal);
  if (signal == SIGINT) CHECK(128 + WTERMSIG(*status) == 130);
  // Stopped in a few pacing slices, not after the minute the rest of the stream takes.
  CHECK(seconds < 5.0);

  std::smatch counts;
  const std::regex sentOfTotal(R"(lattice: (\d+) of (\d+) bytes went out; to continue from there run:)");
  REQUIRE(std::regex_search(err, counts, sentOfTotal));
  const std::uint64_t sent = std::stoull(counts[1].str());
  CHECK(std::stoull(counts[2].str()) == total);
  CHECK(sent > 0);
  CHECK(sent < total);
  // The command that continues it names the virtual terminal, not the pty it had.
  CHECK_THAT(err, Catch::Contains(fmt::format("lattice send {} --port virtual:tek4125 --baud 1200", stream)) &&
                      Catch::Contains(fmt::format("--resume {}\n", sent)));
  CHECK_THAT(err, Catch::Contains(signal == SIGINT ? "stopped by SIGINT (Ctrl-C)"
                                                   : signal == SIGTERM ? "stopped by SIGTERM" : "stopped by SIGHUP"));
  CHECK_FALSE(std::filesystem::exists(screen));  // no screen of a stream that did not finish
}

// `render --port` records the stream before it sends it, so Ctrl-C during
// its send leaves the recording in place and prints the `lattice send`
// command that continues from it.
TEST_CASE("Ctrl-C during render --port leaves the recording and prints the send --resume command", "[send]") {
  const lattice::testing::TempDir scratch("render-port-interrupt");
  const std::string screen = scratch / "hole.png", recording = scratch / "hole.tek4125";
  const std::string errPath = scratch / "stderr.txt";
  const pid_t pid = startLattice({"render", lattice::testing::sourcePath("scenes/sphere-hole.toml").string(),
                                  "--width", "96", "--height", "72", "--device", "tek4125", "--port",
                                  "virtual:tek4125", "--baud", "1200", "-o", screen, "-q"},
                                 errPath);
  REQUIRE(pid > 0);
  const Clock::time_point started = Clock::now();
  while (readText(errPath).find("a virtual Tektronix 4125") == std::string::npos &&
         Clock::now() < started + std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  ::kill(pid, SIGINT);
  const std::optional<int> status = waitUntil(pid, Clock::now() + std::chrono::seconds(20));
  const std::string err = readText(errPath);
  INFO(err);
  REQUIRE(status.has_value());
  REQUIRE(WIFSIGNALED(*status));
  CHECK(WTERMSIG(*status) == SIGINT);
  REQUIRE(std::filesystem::exists(recording));  // landed before the first byte went out
  std::smatch counts;
  REQUIRE(std::regex_search(err, counts, std::regex(R"(lattice: (\d+) of (\d+) bytes went out)")));
  CHECK(std::stoull(counts[2].str()) == std::filesystem::file_size(recording));
  CHECK_THAT(err, Catch::Contains(fmt::format("lattice send {} --port virtual:tek4125 --baud 1200", recording)) &&
                      Catch::Contains(fmt::format("--resume {}", counts[1].str())));
  CHECK_FALSE(std::filesystem::exists(screen));  // no screen of a stream that did not finish
}
