// Real producer streams: gnuplot (the Debian package, scripts/setup.sh
// installs gnuplot-nox) writes a plot with its tek410x and tek40xx
// terminals at test time, and the emulator must draw the plot's frame and
// its line where gnuplot put them. Skipped, with a message, where gnuplot is
// missing. Text is not drawn (the emulator has no fonts).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "tests/support/temp_dir.hpp"

using namespace lattice;
using namespace lattice::tek4125;

namespace {

// False, with a warning saying why, where gnuplot is not installed.
bool haveGnuplot() {
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) return true;
  WARN("gnuplot is not installed: skipped (scripts/setup.sh installs gnuplot-nox)");
  return false;
}

// The plot: frame from 0.25 to 0.75 of the terminal's drawing area on both
// axes, y = x from corner to corner, no key.
std::vector<std::uint8_t> plotWith(const std::string& terminal, const lattice::testing::TempDir& dir) {
  const std::string script = dir / "plot.gp", output = dir / "plot.tek";
  std::ofstream(script) << fmt::format(
      "set terminal {}\nset output '{}'\nunset key\n"
      "set lmargin at screen 0.25\nset rmargin at screen 0.75\n"
      "set bmargin at screen 0.25\nset tmargin at screen 0.75\n"
      "set xrange [0:1]\nset yrange [0:1]\nplot x with lines\n",
      terminal, output);
  REQUIRE(std::system(fmt::format("gnuplot '{}' 2>/dev/null", script).c_str()) == 0);
  std::ifstream in(output, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// gnuplot 5.4's tek410x writes its select-code commands with a doubled '%'
// (fputs of a printf format); a terminal cannot take ESC %% as one, and the
// emulator counts each as malformed. Nothing else may be.
long doubledPercents(const std::vector<std::uint8_t>& b) {
  long n = 0;
  for (std::size_t i = 0; i + 2 < b.size(); ++i) n += b[i] == 0x1B && b[i + 1] == '%' && b[i + 2] == '%';
  return n;
}

struct Geometry {
  int xmax, ymax;  // the largest coordinates gnuplot uses (term/t410x.trm, term/tek.trm); it rounds f * max
  int scale;       // to the 4100's 12-bit space: 1 for 4096-wide coordinates, 4 for 1024-wide 4010 ones
};

// Emulator pixel (column, image row) of a fraction of gnuplot's drawing area.
std::pair<int, int> pixelOf(const Geometry& g, double fx, double fy) {
  const int x = static_cast<int>(std::lround(fx * g.xmax)) * g.scale;
  const int y = static_cast<int>(std::lround(fy * g.ymax)) * g.scale;
  return {x * 1280 / 4096, 1023 - y * 1280 / 4096};
}

// Drawn in `index` within `r` pixels of (px, py)?
bool near(const IndexedImage& img, int px, int py, int index, int r) {
  for (int y = py - r; y <= py + r; ++y)
    for (int x = px - r; x <= px + r; ++x)
      if (x >= 0 && y >= 0 && x < img.width && y < img.height && img.at(x, y) == index) return true;
  return false;
}

void checkPlot(const std::vector<std::uint8_t>& stream, const Geometry& g, int lineIndex, int frameIndex) {
  Tek4125Decoder decoder{Tek4125Profile{}};
  decoder.feed(stream);
  decoder.finish();
  CHECK(decoder.report().unknownCommands == 0);
  CHECK(static_cast<long>(decoder.report().malformed) == doubledPercents(stream));
  const IndexedImage& img = decoder.image();
  long drawn = 0;
  for (PaletteIndex p : img.pixels) drawn += p != 0;
  CHECK(drawn > 1000);
  // The frame's four sides, sampled along their length.
  long sideSamples = 0, sideHits = 0;
  for (double t = 0.26; t < 0.75; t += 0.01)
    for (auto [fx, fy] : {std::pair{t, 0.25}, std::pair{t, 0.75}, std::pair{0.25, t}, std::pair{0.75, t}}) {
      const auto [px, py] = pixelOf(g, fx, fy);
      ++sideSamples;
      sideHits += near(img, px, py, frameIndex, 1);
    }
  CHECK(sideHits == sideSamples);
  // y = x from the frame's lower-left to its upper-right corner.
  for (double t = 0.05; t < 1.0; t += 0.05) {
    const auto [px, py] = pixelOf(g, 0.25 + 0.5 * t, 0.25 + 0.5 * t);
    INFO("t " << t << " pixel " << px << "," << py);
    CHECK(near(img, px, py, lineIndex, 2));
  }
  // Nothing outside the frame but tick labels' absence: the corners of the
  // screen stay clear.
  CHECK(img.at(5, 5) == 0);
  CHECK(img.at(1274, 1018) == 0);
}

}  // namespace

TEST_CASE("gnuplot's tek410x terminal: the plot's frame and line land where gnuplot put them") {
  if (!haveGnuplot()) return;
  const lattice::testing::TempDir dir("gnuplot-410x");
  const auto stream = plotWith("tek410x", dir);
  REQUIRE(stream.size() > 200);
  // t410x.trm: 4095 x 3131; the frame in ML? (15), the first plot line in ML 2.
  checkPlot(stream, Geometry{4095, 3131, 1}, 2, 15);
}

TEST_CASE("gnuplot's tek40xx terminal: 4010 vectors with raw DEL bytes land where gnuplot put them") {
  if (!haveGnuplot()) return;
  const lattice::testing::TempDir dir("gnuplot-40xx");
  const auto stream = plotWith("tek40xx", dir);
  REQUIRE(stream.size() > 200);
  bool hasDel = false;
  for (std::uint8_t c : stream) hasDel = hasDel || c == 0x7F;
  CHECK(hasDel);  // a Lo-Y of 31: DEL is data here
  // tek.trm: TEK40XMAX 1024 by TEK40YMAX 780, so coordinates 0..1023 and
  // 0..779 in 10-bit 4010 form; everything in the line index 1.
  checkPlot(stream, Geometry{1023, 779, 4}, 1, 1);
}
