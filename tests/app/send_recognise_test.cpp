// `lattice send` recognises the stream before a byte goes on the line, the
// way `lattice emulate` does: a PNG, a scene, noise or another terminal's
// stream is refused with exit 3 saying what it is, and the terminal (a pty
// peer here) receives nothing; --raw sends the bytes anyway.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "foundation/system/atomic_file.hpp"
#include "io/pty.hpp"
#include "tests/io/pty_peer.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"

using lattice::testing::goldenPath;
using lattice::testing::PtyPeer;
using lattice::testing::runLattice;
using lattice::testing::sourcePath;

TEST_CASE("send refuses what is not a terminal stream, and the line carries nothing", "[send]") {
  const lattice::testing::TempDir scratch("send-recognise");
  const std::string noise = scratch / "noise.bin";
  lattice::writeFileAtomically(noise, lattice::testing::pseudoRandomBytes(256 * 1024, 28));
  const std::string empty = scratch / "empty.tek";
  { std::ofstream touch(empty); }
  const std::string png = goldenPath("tek4027/rings-48x32-screen.png").string();
  struct Case {
    std::string file;
    std::string flags;  // after --port PTY
    std::string says;
  };
  const Case cases[] = {
      {png, "", "this is a PNG image, not a stream of any device"},
      {noise, "", "this is binary data, not a stream of any device"},
      {sourcePath("scenes/sphere-hole.toml").string(), "", "render it to a stream first"},
      {empty, "", "this is an empty file"},
      {png, "--device tek4125", "this is a PNG image, not a Tektronix 4125 stream"},
      {noise, "--device tek4027", "this is binary data, not a Tektronix 4027 stream"},
      // Another terminal's stream: the device to name instead.
      {goldenPath("tek4027/rings-48x32.tek").string(), "--device tek4125", "send it with --device tek4027"},
  };
  for (const Case& c : cases) {
    lattice::io::PtyPair pty;
    PtyPeer peer(pty);
    const auto run =
        runLattice(fmt::format("send '{}' --port {} --baud 115200 {}", c.file, pty.slavePath(), c.flags));
    INFO(c.file << " " << c.flags << ": " << run.stderrText);
    CHECK(run.exitCode == 3);
    CHECK_THAT(run.stderrText, Catch::StartsWith("lattice: error: ") && Catch::Contains(c.says) &&
                                   Catch::Contains("--raw sends the bytes anyway"));
    peer.settle(0.05);
    CHECK(peer.received() == 0);
  }
}

TEST_CASE("send to a virtual terminal refuses a PNG before the terminal is started", "[send]") {
  const lattice::testing::TempDir scratch("send-recognise-virtual");
  const std::string screen = scratch / "screen.png";
  const auto run = runLattice(fmt::format("send '{}' --port virtual:tek4125 -o '{}'",
                                          goldenPath("tek4027/rings-48x32-screen.png").string(), screen));
  INFO(run.stderrText);
  CHECK(run.exitCode == 3);
  CHECK_THAT(run.stderrText, Catch::Contains("this is a PNG image, not a Tektronix 4125 stream"));
  CHECK_THAT(run.stderrText, !Catch::Contains("a virtual Tektronix"));  // no pty, no emulator, no bytes
  CHECK_FALSE(std::filesystem::exists(screen));
  // A Tek 4014 stream names its own virtual terminal.
  const auto other = runLattice(fmt::format("send '{}' --port virtual:tek4027 -o '{}'",
                                            goldenPath("tek4014/rings-96x64.tek").string(), screen));
  CHECK(other.exitCode == 3);
  CHECK_THAT(other.stderrText, Catch::Contains("send it to --port virtual:tek4014"));
}

TEST_CASE("send --raw sends the bytes anyway, and a stream passes without --raw", "[send]") {
  const lattice::testing::TempDir scratch("send-raw");
  const std::string noise = scratch / "noise.bin";
  const std::vector<std::uint8_t> bytes = lattice::testing::pseudoRandomBytes(64 * 1024, 1988);
  lattice::writeFileAtomically(noise, bytes);
  {
    lattice::io::PtyPair pty;
    PtyPeer peer(pty);
    const auto run = runLattice(fmt::format("send '{}' --port {} --baud 115200 --raw", noise, pty.slavePath()));
    INFO(run.stderrText);
    CHECK(run.exitCode == 0);
    REQUIRE(peer.waitFor(bytes.size()));
    peer.settle(0.05);
    CHECK(peer.data() == bytes);
  }
  // Every terminal's stream goes without --device: the 4014's, which the
  // 4125's recogniser takes too, and the 4027's.
  for (const char* golden : {"tek4014/rings-96x64.tek", "tek4027/rings-48x32.tek", "tek4125/scene24x16_4planes.tek"}) {
    const std::string stream = goldenPath(golden).string();
    lattice::io::PtyPair pty;
    PtyPeer peer(pty);
    const auto run = runLattice(fmt::format("send '{}' --port {} --baud 115200", stream, pty.slavePath()));
    INFO(golden << ": " << run.stderrText);
    CHECK(run.exitCode == 0);
    CHECK(peer.waitFor(std::filesystem::file_size(stream)));
  }
}
