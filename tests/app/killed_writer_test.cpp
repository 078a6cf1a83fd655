// Writers killed at random moments: the real `lattice` binary is
// started, sent SIGINT, SIGTERM or SIGHUP after a random delay, and the
// output directory must then hold the old output or the new one, whole,
// and nothing else (no "<out>.tmp-PID-N" left behind).
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "foundation/system/atomic_file.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

extern char** environ;

using namespace lattice;
namespace fs = std::filesystem;

namespace {

struct Outcome {
  bool killed = false;  // died of the signal (rather than finishing first)
  double seconds = 0;
};

// Runs lattice with `args`, output to /dev/null; kills it after `delay`
// (never, when delay is negative).
Outcome runAndKill(const std::vector<std::string>& args, std::chrono::microseconds delay, int signal) {
  std::vector<std::string> argv{lattice::testing::latticeBinary().string()};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> raw;
  for (auto& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, raw[0], &actions, nullptr, raw.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  REQUIRE(spawned == 0);
  if (delay.count() >= 0) {
    std::this_thread::sleep_for(delay);
    ::kill(pid, signal);
  }
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  Outcome o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.killed = WIFSIGNALED(status) && WTERMSIG(status) == signal;
  if (!o.killed) CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  return o;
}

std::vector<std::uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

// Kills `args` (which write `outputs` in `dir`) `rounds` times at delays
// spread over one undisturbed run, and checks what is left each time.
void killAtRandom(const fs::path& dir, const std::vector<std::string>& args, const std::vector<fs::path>& outputs,
                  int rounds) {
  // The new outputs, from a run left alone.
  const Outcome clean = runAndKill(args, std::chrono::microseconds(-1), SIGTERM);
  REQUIRE_FALSE(clean.killed);
  std::vector<std::vector<std::uint8_t>> fresh;
  for (const fs::path& out : outputs) fresh.push_back(readWholeFile(out));
  const std::vector<std::uint8_t> old = bytesOf("the old output\n");

  std::mt19937 random(15);
  const int signals[] = {SIGINT, SIGTERM, SIGHUP};
  std::uniform_int_distribution<long> delayUs(0, static_cast<long>(clean.seconds * 1.1e6));
  int killed = 0;
  for (int round = 0; round < rounds; ++round) {
    for (const fs::path& out : outputs) writeFileAtomically(out, old);
    const int signal = signals[round % 3];
    killed += runAndKill(args, std::chrono::microseconds(delayUs(random)), signal).killed;
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
      ++files;
      INFO("round " << round << ", signal " << signal << ": " << entry.path().filename().string());
      CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
    }
    CHECK(files == outputs.size() + 1);  // the outputs and the input
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      const std::vector<std::uint8_t> now = readWholeFile(outputs[i]);
      INFO("round " << round << ": " << outputs[i].filename().string() << " is neither the old nor the new file");
      CHECK((now == old || now == fresh[i]));
    }
  }
  CHECK(killed > 0);  // the signals did land while the command ran
}

}  // namespace

TEST_CASE("lattice emulate killed at random leaves the old or the new PNG and no temporary", "[signals]") {
  const lattice::testing::TempDir scratch("killed-emulate");
  // A stream of many small random rectangle fills: a noisy screen, whose PNG
  // takes a while to encode and write.
  std::vector<std::uint8_t> stream;
  std::mt19937 random(1);
  auto xy = [&](int x, int y) {
    stream.insert(stream.end(), {static_cast<std::uint8_t>(0x20 | (y >> 7)),
                                 static_cast<std::uint8_t>(0x60 | (y & 3) << 2 | (x & 3)),
                                 static_cast<std::uint8_t>(0x60 | ((y >> 2) & 31)),
                                 static_cast<std::uint8_t>(0x20 | (x >> 7)),
                                 static_cast<std::uint8_t>(0x40 | ((x >> 2) & 31))});
  };
  for (int i = 0; i < 40000; ++i) {
    const int x = static_cast<int>(random() % 1270), y = static_cast<int>(random() % 1014);
    stream.insert(stream.end(), {0x1B, 'R', 'R'});
    xy(x, y);
    xy(x + static_cast<int>(random() % 10), y + static_cast<int>(random() % 10));
    stream.push_back(static_cast<std::uint8_t>(0x30 | (random() % 16)));
  }
  const fs::path input = scratch.path() / "noise.tek";
  writeFileAtomically(input, stream);
  const fs::path png = scratch.path() / "screen.png";
  killAtRandom(scratch.path(), {"emulate", "--device", "tek4125", input.string(), "-o", png.string()}, {png}, 45);
}

TEST_CASE("lattice render killed at random leaves old or new stream and PNG and no temporary", "[signals]") {
  const lattice::testing::TempDir scratch("killed-render");
  const fs::path scene = scratch.path() / "scene.toml";
  fs::copy_file(fs::path(LATTICE_SOURCE_DIR) / "scenes" / "torus-floor.toml", scene);
  const fs::path stream = scratch.path() / "out.tek", png = scratch.path() / "out.png";
  killAtRandom(scratch.path(),
               {"render", scene.string(), "--width", "160", "--height", "120", "--threads", "1", "--device",
                "tek4125", "--stream", stream.string(), "-o", png.string()},
               {stream, png}, 45);
}
