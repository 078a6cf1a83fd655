// `lattice send` end to end: the built binary streams a file into a pty
// whose master side is the terminal. Needs the `lattice` target built
// (LATTICE_BINARY_DIR/app/lattice, or $LATTICE_EXE; test_io depends on it);
// the io-level behaviour is covered by flow_control_test.cpp as well.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "foundation/atomic_file.hpp"
#include "io/pty.hpp"
#include "tests/support/run_lattice.hpp"
#include "pty_peer.hpp"

using namespace lattice;
using namespace lattice::io;
using lattice::testing::PtyPeer;


TEST_CASE("lattice send streams a file to a pty, and resumes after a stall", "[send]") {
  // test_io depends on the `lattice` target (tests/CMakeLists.txt), so a
  // missing binary means a broken build: fail rather than skip quietly.
  INFO("lattice is not built (" << lattice::testing::latticeBinary() << "): build the `lattice` target or set LATTICE_EXE");
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  auto stream = lattice::testing::pseudoRandomBytes(80 * 1024, 2024);
  auto file = std::filesystem::temp_directory_path() / fmt::format("lattice-send-test-{}.tek", ::getpid());
  writeFileAtomically(file, stream);

  PtyPair pty;
  PtyPeer peer(pty);
  peer.holdAt(20 * 1024);
  std::jthread terminal([&] { peer.stopSenderAt(20 * 1024); });
  auto stalled = lattice::testing::runLattice(fmt::format("send '{}' --port {} --baud 38400 --flow xonxoff --stall-timeout 0.5",
                                        file.string(), pty.slavePath()));
  terminal.join();
  CHECK(stalled.exitCode == 6);
  auto at = stalled.stderrText.find("--resume ");
  REQUIRE(at != std::string::npos);
  std::uint64_t resume = std::stoull(stalled.stderrText.substr(at + 9));
  peer.settle();
  CHECK(peer.received() == resume);
  CHECK(stalled.stderrText.find(fmt::format("lattice send {} --port {}", file.string(), pty.slavePath())) !=
        std::string::npos);

  peer.send(lattice::testing::kXon);
  auto resumed = lattice::testing::runLattice(fmt::format("send '{}' --port {} --baud 38400 --flow xonxoff --resume {}",
                                        file.string(), pty.slavePath(), resume));
  CHECK(resumed.exitCode == 0);
  REQUIRE(peer.waitFor(stream.size()));
  peer.settle(0.05);
  CHECK(peer.data() == stream);

  auto pastEnd = lattice::testing::runLattice(fmt::format("send '{}' --port {} --resume 999999999", file.string(), pty.slavePath()));
  CHECK(pastEnd.exitCode == 2);
  auto noPort = lattice::testing::runLattice(fmt::format("send '{}' --port /dev/lattice-no-such-tty", file.string()));
  CHECK(noPort.exitCode == 5);
  CHECK(noPort.stderrText.find("no such serial port") != std::string::npos);
  auto noFile = lattice::testing::runLattice(fmt::format("send /nonexistent/lattice.tek --port {}", pty.slavePath()));
  CHECK(noFile.exitCode == 3);
  CHECK(noFile.stderrText.find("/nonexistent/lattice.tek") != std::string::npos);
  std::filesystem::remove(file);
}
