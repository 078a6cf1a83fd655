// Our 4014 streams in a real xterm's Tek window (`xterm -t`, Debian's xterm
// under Xvfb, tests/support/xterm_capture.hpp), compared pixel for pixel with
// what our emulator shows, scaled as xterm scales the Tek space to its window
// (Tekproc.c: scale = min(width / 4096, height / (3072 + 34 + 23)); a 12-bit
// point (X, Y) lands at (int)(X * scale + border), (int)((3106 - Y) * scale +
// border), border 0 here). Every pixel of the window must be within 1 level.
// Skips with the reason where Xvfb, xterm or xwd is missing.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/png.hpp"
#include "tests/devices/tek4014/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/support/golden.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xterm_capture.hpp"

using namespace lattice;
using namespace lattice::tek4014;
using namespace lattice::testing;

namespace {

// xterm's Tek window: the Tek space it fits (Tekproc.c TEKWIDTH, and
// TEKHEIGHT + TEKTOPPAD + TEKBOTTOMPAD), and the 12-bit y of its top row.
constexpr int kTekWidth = 4096, kTekFullHeight = 3072 + 34 + 23, kTekTop = 3072 + 34;

// What xterm should show in a width x height window: every lit pixel of our
// emulator's screen, at the 12-bit address it stands for, put where xterm
// puts that address. (Our streams draw dots and horizontal runs only, and a
// scale at most 1 maps consecutive addresses to the same or the next pixel,
// so the runs xterm draws between scaled ends are these pixels exactly.)
RgbImage expectedWindow(const IndexedImage& screen, int shift, int width, int height) {
  const double scale = std::min(double(width) / kTekWidth, double(height) / kTekFullHeight);
  RgbImage out(width, height);  // black
  for (int sy = 0; sy < screen.height; ++sy)
    for (int x = 0; x < screen.width; ++x) {
      if (screen.at(x, sy) == 0) continue;
      const int X = x << shift, Y = (screen.height - 1 - sy) << shift;
      const int wx = static_cast<int>(X * scale), wy = static_cast<int>((kTekTop - Y) * scale);
      if (wx < 0 || wy < 0 || wx >= width || wy >= height) continue;
      std::uint8_t* p = out.pixel(wx, wy);
      p[0] = p[1] = p[2] = 255;
    }
  return out;
}

void compareInXterm(const std::string& name, const IndexedImage& img, const Tek4014Profile& profile,
                    const std::vector<std::string>& geometry) {
  TempDir dir("tek4014-xterm");
  auto stream = test::driveFrame(img, profile);
  // The driver leaves the terminal in alpha mode, where xterm draws its text
  // cursor; GS (graph mode, nothing drawn) hides it for the capture.
  stream.push_back(static_cast<std::uint8_t>(kGraph));
  const std::string file = dir / (name + ".tek");
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(stream.data()), static_cast<std::streamsize>(stream.size()));
  }
  XtermCaptureOptions options;
  options.xtermArguments = {"-t", "-fg", "white", "-bg", "black"};
  options.xtermArguments.insert(options.xtermArguments.end(), geometry.begin(), geometry.end());
  options.streamFile = file;
  options.windowName = "tektronix(Tek)";
  const XtermCapture capture = captureXterm(options);
  if (!capture.captured()) {
    WARN("skipped: " << capture.skipReason);
    return;
  }
  const Tek4014Decoder d = test::decode(stream, profile);
  const RgbImage want = expectedWindow(d.image(), profile.shift(), capture.window.width, capture.window.height);
  const ImageDifference diff = compareImages(capture.window, want);
  INFO(name << ": window " << capture.window.width << "x" << capture.window.height << ", " << diff.differingPixels
            << " pixels differ, largest by " << diff.maxChannelDelta);
  if (diff.maxChannelDelta > 1) {  // keep both pictures for a look, in the build tree
    const std::filesystem::path keep = std::filesystem::path(LATTICE_BINARY_DIR) / "tek4014-xterm";
    std::filesystem::create_directories(keep);
    io::writePng(keep / (name + "-xterm.png"), capture.window);
    io::writePng(keep / (name + "-expected.png"), want);
    WARN("pictures kept in " << keep.string());
  }
  CHECK(diff.maxChannelDelta <= 1);
  long lit = 0;
  for (std::size_t i = 0; i < want.rgb.size(); i += 3) lit += want.rgb[i] != 0;
  CHECK(lit > 100);  // the comparison saw a picture, not two black windows
}

}  // namespace

TEST_CASE("xterm -t draws our 10-bit stream as our emulator does (window 1024x783: one pixel an address)") {
  // Points and vectors both: rings (scattered dots and solid areas) and a gradient.
  compareInXterm("rings-10bit", testing::ringsImage(256, 160), Tek4014Profile{},
                 {"-xrm", "XTerm*tekGeometry: 1024x783"});
  Tek4014Profile ordered;
  ordered.dither = Tek4014Dither::Ordered;
  compareInXterm("gradient-ordered", testing::gradientImage(200, 120), ordered,
                 {"-xrm", "XTerm*tekGeometry: 1024x783"});
}

TEST_CASE("xterm -t draws our 12-bit stream as our emulator does, scaled to its default window") {
  Tek4014Profile twelve;
  twelve.addressBits = 12;
  compareInXterm("rings-12bit", testing::ringsImage(640, 400), twelve, {});
}
