// The serial path end to end, with a pseudo-terminal as the terminal: a
// render goes through the Tek 4125 driver into a SerialSink on the pty's
// slave side while a reader thread feeds the master side into the emulator,
// as a terminal on a cable would draw. The bytes and the picture must equal
// what the file path (MemorySink, AtomicFile) gives for the same render. The
// second test does the same with the built `lattice` binary (--port against
// --stream), so the CLI's transport choice is covered too.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/png.hpp"
#include "io/pty.hpp"
#include "tests/support/run_lattice.hpp"
#include "io/serial_options.hpp"
#include "io/serial_sink.hpp"
#include "quantize/run_pipeline.hpp"
#include "render/renderer.hpp"
#include "loader/scene_loader.hpp"
#include "tests/support/golden.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::quantize;

namespace {

// The terminal: reads the pty master on its own thread and draws every chunk
// as it arrives. Waits are bounded so a broken sender fails the test rather
// than hanging it.
class PtyTerminal {
 public:
  PtyTerminal(PtyPair& pty, const devices::Device& device) : pty_(pty), decoder_(device.makeEmulator()) {
    ::fcntl(pty_.masterFd(), F_SETFL, ::fcntl(pty_.masterFd(), F_GETFL) | O_NONBLOCK);
    reader_ = std::thread([this] { readLoop(); });
  }
  ~PtyTerminal() { stop(); }
  PtyTerminal(const PtyTerminal&) = delete;
  PtyTerminal& operator=(const PtyTerminal&) = delete;

  // True once n bytes arrived and then nothing more for a moment (so a
  // stream longer than expected would be seen whole).
  bool waitFor(std::size_t n, double seconds = 10.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (received() < n) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return true;
  }
  // Stops reading and finishes the decoder; after this the results are stable.
  void stop() {
    stop_ = true;
    if (reader_.joinable()) reader_.join();
    if (!finished_) {
      decoder_->finish();
      finished_ = true;
    }
  }
  std::size_t received() const {
    std::lock_guard lock(mutex_);
    return bytes_.size();
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  const StreamDecoder& decoder() const { return *decoder_; }

 private:
  void readLoop() {
    std::vector<std::uint8_t> buffer(4096);
    while (!stop_) {
      pollfd entry{pty_.masterFd(), POLLIN, 0};
      if (::poll(&entry, 1, 10) <= 0) continue;
      const ssize_t n = ::read(pty_.masterFd(), buffer.data(), buffer.size());
      if (n <= 0) {
        // EAGAIN, or EIO while no process holds the slave open: try again.
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        continue;
      }
      const std::span<const std::uint8_t> chunk(buffer.data(), static_cast<std::size_t>(n));
      decoder_->feed(chunk);  // only this thread touches the decoder until stop()
      std::lock_guard lock(mutex_);
      bytes_.insert(bytes_.end(), chunk.begin(), chunk.end());
    }
  }

  PtyPair& pty_;
  std::unique_ptr<StreamDecoder> decoder_;
  std::thread reader_;
  std::atomic<bool> stop_{false};
  bool finished_ = false;
  mutable std::mutex mutex_;
  std::vector<std::uint8_t> bytes_;
};

std::filesystem::path tempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() / fmt::format("lattice-serial-render-{}-{}", ::getpid(), name);
}

std::vector<std::uint8_t> decodeToPngBytes(const devices::Device& device, std::span<const std::uint8_t> stream,
                                           const std::filesystem::path& png) {
  auto decoder = device.makeEmulator();
  decoder->feed(stream);
  decoder->finish();
  writePng(png, toRgbImage(decoder->image()));
  return readWholeFile(png);
}

}  // namespace

TEST_CASE("serial render: a scene through a pty equals the file path", "[serial]") {
  const devices::Device device = devices::makeDevice("tek4125");
  const SceneDesc scene = loadScene(testing::sourcePath("scenes/sphere-hole.toml"));
  RenderSettings settings;
  settings.width = 64;
  settings.height = 64;
  settings.threads = 2;
  Renderer<double> renderer(scene, settings);
  PipelineOptions options;
  options.progress = false;

  // The file path: the stream in memory and through an atomic file.
  MemorySink memory;
  {
    auto driver = device.makeDriver(memory);
    runPipeline(renderer, driver->sink(), options);
  }
  const auto streamFile = tempPath("file.tek");
  {
    AtomicFile file(streamFile);
    auto driver = device.makeDriver(file);
    runPipeline(renderer, driver->sink(), options);
    file.close();
  }
  const std::vector<std::uint8_t> fromFile = readWholeFile(streamFile);
  REQUIRE(memory.data().size() > 1000);
  CHECK(fromFile == memory.data());

  // The serial path: the same render into the pty while the terminal draws.
  PtyPair pty;
  PtyTerminal terminal(pty, device);
  SerialOptions serial;
  serial.port = pty.slavePath();
  serial.baud = 38400;
  serial.flow = FlowControl::XonXoff;
  serial.stallTimeoutSeconds = 5.0;
  std::uint64_t sent = 0;
  {
    auto sink = openSerialSink(serial);
    auto driver = device.makeDriver(*sink);
    runPipeline(renderer, driver->sink(), options);
    sink->close();  // drains the line
    sent = sink->bytesWritten();
  }
  CHECK(sent == memory.data().size());
  REQUIRE(terminal.waitFor(memory.data().size()));
  terminal.stop();
  CHECK(terminal.bytes() == memory.data());
  CHECK(terminal.decoder().report().malformed == 0);
  CHECK(terminal.decoder().report().unknownCommands == 0);

  // Identical pictures, compared as the PNG files the two paths produce.
  const auto filePng = tempPath("file.png"), serialPng = tempPath("serial.png");
  const std::vector<std::uint8_t> filePngBytes = decodeToPngBytes(device, fromFile, filePng);
  writePng(serialPng, toRgbImage(terminal.decoder().image()));
  CHECK(readWholeFile(serialPng) == filePngBytes);
  const testing::ImageDifference d = testing::compareImages(readPng(serialPng), readPng(filePng));
  CHECK(d.differingPixels == 0);
  for (const auto& p : {streamFile, filePng, serialPng}) std::filesystem::remove(p);
}


TEST_CASE("serial render: lattice render --port into a pty equals --stream", "[serial]") {
  // Built with test_io (add_dependencies in tests/CMakeLists.txt): a missing
  // binary is a broken build, not a reason to skip.
  INFO("binary " << lattice::testing::latticeBinary().string() << " (build the `lattice` target, or set LATTICE_EXE)");
  REQUIRE(std::filesystem::exists(lattice::testing::latticeBinary()));
  const devices::Device device = devices::makeDevice("tek4125");
  const std::string scene = testing::sourcePath("scenes/torus-floor.toml").string();
  const std::string common = fmt::format("render '{}' --device tek4125 --width 80 --height 60", scene);

  const auto streamFile = tempPath("cli.tek"), streamPng = tempPath("cli-stream.png"),
             portPng = tempPath("cli-port.png");
  const lattice::testing::CommandRun toFile = lattice::testing::runLattice(fmt::format("{} --stream '{}' -o '{}'", common, streamFile.string(), streamPng.string()));
  INFO("--stream run: " << toFile.stderrText);
  REQUIRE(toFile.exitCode == 0);
  const std::vector<std::uint8_t> fromFile = readWholeFile(streamFile);
  REQUIRE(fromFile.size() > 1000);

  PtyPair pty;
  PtyTerminal terminal(pty, device);
  const lattice::testing::CommandRun toPort = lattice::testing::runLattice(
      fmt::format("{} --port {} --baud 38400 -o '{}'", common, pty.slavePath(), portPng.string()));
  INFO("--port run: " << toPort.stderrText);
  REQUIRE(toPort.exitCode == 0);
  REQUIRE(terminal.waitFor(fromFile.size()));
  terminal.stop();
  CHECK(terminal.bytes() == fromFile);
  CHECK(terminal.decoder().report().malformed == 0);

  // The binary's own emulator pictures of both runs, and the one our
  // terminal drew from the pty, are the same picture.
  const RgbImage drawn = toRgbImage(terminal.decoder().image());
  CHECK(readWholeFile(portPng) == readWholeFile(streamPng));
  const RgbImage fromCli = readPng(portPng);
  const testing::ImageDifference d = testing::compareImages(fromCli, drawn);
  INFO("the CLI's -o is " << fromCli.width << "x" << fromCli.height << ", the pty terminal's screen "
                          << drawn.width << "x" << drawn.height);
  CHECK(d.differingPixels == 0);
  // --port recorded the stream beside the picture (cli-port.tek4125), and it is what went out.
  const auto recording = tempPath("cli-port.tek4125");
  CHECK(readWholeFile(recording) == fromFile);
  for (const auto& p : {streamFile, streamPng, portPng, recording}) std::filesystem::remove(p);
}
