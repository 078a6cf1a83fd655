// The firmware end to end (docs/firmware.md): two example scenes, one with a
// lattice, baked, built for the Cortex-M3 and run under QEMU's mps2-an385
// by scripts/firmware.sh, and the lattice one again on the STM32F405 of
// QEMU's netduinoplus2 (its USART1, the part's 128 KiB), beside Plate 6
// (1000 lattice instances baked as constant data, the 4125 driver streaming
// with --set strategy=runs). Asserted: the firmware exits 0; its UART stream is
// byte for byte what the host writes with `lattice render --arith fixed
// --device tek4125` at the same size with the same (small) histogram; the
// report's RAM high-water mark is within the board's budget (256 KiB, or
// the STM32F405's 128 KiB); the decoded
// picture equals its golden (tests/golden/firmware/). Where the ARM
// toolchain or QEMU is missing the cases pass with a warning saying so.
// The ARM image is built in the source tree's build-firmware/ whichever host
// build runs the test (it does not depend on the host's compiler or
// sanitizers), so the g++ and the sanitizer suites build it once.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_driver.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "foundation/system/atomic_file.hpp"
#include "foundation/indexed_image.hpp"
#include "foundation/rgb_image.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/run_lattice.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lattice;

bool haveTool(const std::string& tool) { return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0; }

bool firmwareToolsPresent() {
  for (const char* tool : {"arm-none-eabi-g++", "qemu-system-arm"})
    if (!haveTool(tool)) {
      WARN(fmt::format("{} is not installed: firmware test skipped (scripts/setup.sh --firmware installs it)", tool));
      return false;
    }
  return true;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// set: one Tek 4125 profile setting (key=value) given to both the bake and
// the host, or empty; golden: compare the decoded picture with its golden.
void runScene(const std::string& scene, const std::string& board = "mps2-an385", std::uint64_t budget = 262144,
              const std::string& set = "", bool golden = true) {
  if (!firmwareToolsPresent()) return;
  const std::string stem = fs::path(scene).stem().string();
  const fs::path out = fs::path(LATTICE_BINARY_DIR) / "firmware-test" / board / stem;
  fs::create_directories(out);
  std::string name = stem + "-64x64";
  if (!set.empty()) name += "-";  // as scripts/firmware.sh names it: the setting's letters and digits
  for (char c : set)
    if (std::isalnum(static_cast<unsigned char>(c))) name += c;
  const std::string setFlag = set.empty() ? "" : " --set " + set;

  const std::string command =
      fmt::format("cd {} && LATTICE_EXE={} bash scripts/firmware.sh {} --board {} --size 64x64{} --out {} >{}/run.log 2>&1",
                  LATTICE_SOURCE_DIR, lattice::testing::latticeBinary().string(), scene, board, setFlag, out.string(),
                  out.string());
  const int status = std::system(command.c_str());
  INFO(readText(out / "run.log"));
  REQUIRE(status == 0);

  // The host's stream, same size, same settings, same histogram form.
  const fs::path hostStream = out / "host.tek";
  const auto host = lattice::testing::runLattice(
      fmt::format("render {}/{} --arith fixed --device tek4125 --width 64 --height 64 --histogram small -q "
                  "--stream {}{}",
                  LATTICE_SOURCE_DIR, scene, hostStream.string(), setFlag));
  INFO(host.stderrText);
  REQUIRE(host.exitCode == 0);
  const std::vector<std::uint8_t> mcu = readWholeFile(out / (name + ".tek"));
  const std::vector<std::uint8_t> ours = readWholeFile(hostStream);
  REQUIRE(mcu.size() > 100);
  CHECK(mcu.size() == ours.size());
  CHECK(mcu == ours);

  // The firmware's own report: the board it ran on, RAM peak within its budget.
  const std::string report = readText(out / (name + ".report"));
  CHECK(report.find("fixed-point on " + board) != std::string::npos);
  std::smatch m;
  REQUIRE(std::regex_search(report, m, std::regex(R"(RAM peak (\d+) B of (\d+))")));
  CHECK(std::stoull(m[2]) == budget);
  CHECK(std::stoull(m[1]) <= budget);
  // What the set-up leaves on the heap: with a scatter baked as constant data
  // it is a few NodeDescs and primitives, not one object per instance.
  std::smatch setUp;
  REQUIRE(std::regex_search(report, setUp, std::regex(R"(the scene set up holds (\d+) B of heap)")));
  CHECK(std::stoull(setUp[1]) <= 16384);

  if (!golden) return;
  // The picture the stream draws, cut out of the screen, is the golden.
  const tek4125::Tek4125Profile profile;
  auto decoder = tek4125::makeTek4125Decoder(profile);
  decoder->feed(mcu);
  decoder->finish();
  CHECK(decoder->report().unknownCommands + decoder->report().malformed == 0);
  const IndexedImage& screen = decoder->image();
  const tek4125::Tek4125Placement place = tek4125::placePicture(profile, 64, 64);
  const int top = profile.height - 1 - (place.bottom + 64 - 1);
  IndexedImage picture(64, 64);
  picture.colormap = screen.colormap;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) picture.at(x, y) = screen.at(x + place.left, y + top);
  lattice::testing::checkGoldenPng(fmt::format("firmware/{}_64x64.png", stem), toRgbImage(picture));
}

}  // namespace

TEST_CASE("sphere-hole on the emulated Cortex-M3 streams the host's bytes", "[firmware]") {
  runScene("scenes/sphere-hole.toml");
}

TEST_CASE("the lattice hook on the emulated Cortex-M3 streams the host's bytes", "[firmware]") {
  runScene("scenes/hook.toml");
}

TEST_CASE("the lattice hook on the emulated STM32F405 (netduinoplus2) streams the host's bytes", "[firmware]") {
  runScene("scenes/hook.toml", "netduinoplus2", 131072);
}

// Plate 6 (1000 lattice hairs) in the STM32F405's 128 KiB: its instances and
// their BVH are constant data in flash (lht/leaf/baked_lattice_union.hpp) and
// the "runs" strategy streams rows with no frame (tek4125_driver.hpp). No
// golden: the host's stream with the same setting is the reference.
TEST_CASE("Plate 6 on the emulated STM32F405 (netduinoplus2) fits its RAM and streams the host's bytes",
          "[firmware]") {
  runScene("scenes/fuzzy-sphere-1000.toml", "netduinoplus2", 131072, "strategy=runs", false);
}
