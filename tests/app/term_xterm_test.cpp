// `lattice term` in a real xterm (`-ti vt340`, 256 colour registers) under
// Xvfb, as a person would run it: Plate 6's strict Tek 4125 stream played
// unpaced, drawn as sixels in the xterm it runs in. The xterm window,
// captured with xwd (tests/support/xterm_capture.hpp), must show the
// emulator's screen at the scale shown (the display's own nearest-neighbour
// view, app/term/sixel_view.hpp, of the screen `lattice emulate` draws),
// every gun within one level: the 4125's colour map is whole percents, as
// sixel colours are. Skips with a warning where Xvfb, xterm or xwd is missing.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cstdlib>

#include "app/term/sixel_view.hpp"
#include "devices/device_table.hpp"
#include "foundation/system/atomic_file.hpp"
#include "io/png.hpp"
#include "tests/support/run_lattice.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xterm_capture.hpp"

TEST_CASE("term in xterm -ti vt340 shows Plate 6 as the emulator draws it", "[term][xterm]") {
  if (const std::string missing = lattice::testing::missingXtermPeers(); !missing.empty()) {
    WARN("skipped: " << missing << " missing (scripts/setup.sh --terminals installs them)");
    return;
  }
  const lattice::testing::TempDir scratch("term-xterm");
  const std::string stream = scratch / "plate6.tek";
  auto run = lattice::testing::runLattice(
      fmt::format("render '{}/scenes/fuzzy-sphere-1000.toml' --device tek4125 --width 512 --height 512 --stream '{}' -q",
                  LATTICE_SOURCE_DIR, stream));
  REQUIRE(run.exitCode == 0);

  constexpr int kColumns = 100, kRows = 40;
  lattice::testing::XtermCaptureOptions options;
  options.xtermArguments = {"-ti", "vt340", "-xrm", "XTerm*numColorRegisters: 256", "-geometry",
                            fmt::format("{}x{}", kColumns, kRows)};
  // Its closing summary kept off the screen: it would scroll the picture up a line or two.
  options.command = {"sh", "-c", "exec \"$0\" \"$@\" 2>/dev/null", lattice::testing::latticeBinary().string(), "term",
                     "--stream", stream, "--unpaced", "--snapshot", scratch / "s.png"};
  options.timeoutSeconds = 60;
  const lattice::testing::XtermCapture capture = lattice::testing::captureXterm(options);
  if (!capture.captured()) {
    WARN("skipped: " << capture.skipReason);
    return;
  }
  // The display's geometry is the window's: cells of window / text size.
  const lattice::app::ViewGeometry host{kColumns, kRows, capture.window.width / kColumns,
                                        capture.window.height / kRows, 256};
  const lattice::devices::Device device = lattice::devices::makeDevice("tek4125");
  std::unique_ptr<lattice::StreamDecoder> emulator = device.makeEmulator();
  emulator->feed(lattice::readWholeFile(stream));
  emulator->finish();
  lattice::app::SixelView view(host, device.width, device.height);
  view.update(emulator->image());
  const lattice::IndexedImage shown = view.shown();
  INFO("view " << shown.width << "x" << shown.height << " in a window of " << capture.window.width << "x"
               << capture.window.height);
  REQUIRE(shown.width <= capture.window.width);
  REQUIRE(shown.height <= capture.window.height);
  // LATTICE_KEEP_CAPTURE=PATH keeps the window as a PNG (docs/images/term-xterm-plate6.png is one).
  if (const char* keep = std::getenv("LATTICE_KEEP_CAPTURE")) lattice::io::writePng(keep, capture.window);
  int worst = 0;
  long lit = 0;
  for (int y = 0; y < shown.height; ++y)
    for (int x = 0; x < shown.width; ++x) {
      const lattice::Rgb8 want = shown.colorAt(x, y);
      const std::uint8_t* got = capture.window.pixel(x, y);
      worst = std::max({worst, std::abs(got[0] - want.r), std::abs(got[1] - want.g), std::abs(got[2] - want.b)});
      lit += want.r + want.g + want.b > 0;
    }
  CHECK(lit > shown.width * shown.height / 10);  // the sphere is there to compare
  CHECK(worst <= 1);
}
