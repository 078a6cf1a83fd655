// The emulator on streams a plotting program would send: vectors, panels,
// 4010-style GS runs, mode switches, and what it does with the unknown.
#include <catch2/catch.hpp>

#include <string>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"
#include "tests/devices/tek4125/stream_builder.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

// Screen pixel of terminal coordinate (x, y) on the default 1280x1024 screen.
PaletteIndex at(const Tek4125Decoder& d, int x, int y) {
  return d.image().at(x * 1280 / 4096, 1023 - y * 1280 / 4096);
}

long countIndex(const Tek4125Decoder& d, int index) {
  long n = 0;
  for (PaletteIndex p : d.image().pixels) n += p == index;
  return n;
}

}  // namespace

TEST_CASE("a gnuplot tek410x-style stream draws its vectors in the line index") {
  // What gnuplot's tek410x terminal sends for a frame with a box and a
  // diagonal: init (text attributes, dialog buffer), graphics (clear,
  // hide dialog), line types (ML with MV line style), moves/draws, a text
  // label (LT) and back to ANSI mode.
  Stream s;
  s.raw("\x1b%!0\x1bMN0\x1bMCB7C;\x1bMQ1\x1bMT1\x1bMG1\x1bRK!\x1bSK!\x1bLZ\x1b%!1");
  s.raw("\x1b%!0\x1b\x0c\x1bLV0");
  s.raw("\x1bML5\x1bMV0");
  s.cmd("LF").p(400, 300).cmd("LG").p(3600, 300).cmd("LG").p(3600, 2800).cmd("LG").p(400, 2800).cmd("LG").p(400, 300);
  s.raw("\x1bML2\x1bMV0");
  s.cmd("LF").p(400, 300).cmd("LG").p(3600, 2800);
  s.raw("\x1bMR00");
  s.cmd("LF").p(2000, 2900).raw("\x1bLT").i(5).raw("title");
  s.raw("\x1bLV1\x1b%!1");
  s.raw("gnuplot> ");  // the dialog text that follows in ANSI mode is not graphics
  const Tek4125Decoder d = run(s.bytes);
  CHECK(d.report().unknownCommands == 0);
  CHECK(d.report().malformed == 0);
  CHECK_FALSE(d.inTekMode());
  CHECK(at(d, 2000, 300) == 5);   // bottom edge of the box
  CHECK(at(d, 3600, 1500) == 5);  // right edge
  CHECK(at(d, 2000, 1500) == 0);  // inside the box, off the diagonal
  CHECK(at(d, 2000, 1550) == 2);  // on the diagonal: (400,300)-(3600,2800) passes (2000,1550)
  // Box: 2 * (1000 + 781) pixels around; diagonal about 1000 pixels long.
  CHECK(countIndex(d, 5) > 3000);
  CHECK(countIndex(d, 2) > 900);
}

TEST_CASE("ML with the encoding of 15 and LF/LG clip to the screen without failing") {
  Stream s;
  s.raw("\x1bML?");
  s.cmd("LF").p(0, 4095).cmd("LG").p(4095, 0);  // y above 3276 lies above the 1024-row screen
  const Tek4125Decoder d = run(s.bytes);
  CHECK(d.report().malformed == 0);
  CHECK(countIndex(d, 15) > 1000);
  CHECK(d.image().at(1279, 1023) == 15);  // the end point (4095, 0) is the bottom-right pixel
}

TEST_CASE("4010-style GS runs move to the first point and draw to the rest until US") {
  Stream s;
  s.cmd("ML").i(3);
  s.raw("\x1d").p(100, 100).p(1000, 100).p(1000, 1000);
  s.raw("\x1f");
  s.p(2000, 2000);  // alpha mode: these bytes are text, not a vector
  const Tek4125Decoder d = run(s.bytes);
  CHECK(at(d, 500, 100) == 3);
  CHECK(at(d, 1000, 500) == 3);
  CHECK(at(d, 500, 500) == 0);  // no line from (100,100) to (1000,1000)... the move was dark
  CHECK(at(d, 1500, 1500) == 0);
  CHECK(d.report().malformed == 0);
}

TEST_CASE("panels fill solid with the MP pattern index and draw their boundary if asked") {
  Stream s;
  s.cmd("MP").i(-4).cmd("ML").i(6);
  s.cmd("LP").p(800, 800).i(1).cmd("LG").p(2400, 800).cmd("LG").p(2400, 2000).cmd("LG").p(800, 2000).cmd("LE");
  s.cmd("MP").i(-7);
  s.cmd("LP").p(3000, 200).i(0).cmd("LG").p(3800, 200).cmd("LG").p(3400, 900).cmd("LE");  // triangle
  const Tek4125Decoder d = run(s.bytes);
  CHECK(at(d, 1600, 1400) == 4);  // inside the rectangle
  CHECK(at(d, 800, 1400) == 6);   // its boundary in the line index
  CHECK(at(d, 2600, 1400) == 0);
  CHECK(at(d, 3400, 400) == 7);  // inside the triangle
  CHECK(at(d, 3050, 850) == 0);  // outside it, inside its bounding box
  // The rectangle covers 500 x 375 pixels.
  CHECK(countIndex(d, 4) == Approx(499 * 374).epsilon(0.01));
  CHECK(d.report().malformed == 0);
}

TEST_CASE("page clear, mode switches and ignored dialog-area commands") {
  Stream s;
  s.cmd("ML").i(1).cmd("LF").p(0, 0).cmd("LG").p(4000, 0);
  s.raw("\x1b\x0c");  // clear
  s.raw("\x1bKA1\x1bLV0\x1bLLA0\x1bLBB0\x1bLZ");
  s.raw("\x1b%!1");  // ANSI: Tek commands are not interpreted
  s.cmd("LF").p(0, 100).cmd("LG").p(4000, 100);
  s.raw("\x1b[2J");
  s.raw("\x1b%!0");
  s.cmd("LF").p(0, 200).cmd("LG").p(4000, 200);
  const Tek4125Decoder d = run(s.bytes);
  CHECK(at(d, 2000, 0) == 0);
  CHECK(at(d, 2000, 100) == 0);
  CHECK(at(d, 2000, 200) == 1);
  CHECK(d.report().unknownCommands == 0);
  CHECK(d.report().malformed == 0);
  CHECK(d.inTekMode());
}

TEST_CASE("the colour map loads in RGB, HLS and CMY modes") {
  Stream s;
  s.cmd("TM").i(1).i(1).i(1).cmd("TG").i(1).i(4).i(2).i(100).i(50).i(0);
  s.cmd("TM").i(3).i(1).i(1).cmd("TG").i(1).i(8).i(3).i(120).i(50).i(100).i(4).i(0).i(50).i(100);
  s.cmd("TM").i(2).i(1).i(1).cmd("TG").i(1).i(4).i(5).i(0).i(100).i(100);
  const Tek4125Decoder d = run(s.bytes, Tek4125Profile{});
  const Palette& m = d.image().colormap;
  CHECK(m[2] == Rgb8{255, 128, 0});
  CHECK(m[3] == Rgb8{255, 0, 0});  // Tek hue 120 is red
  CHECK(m[4] == Rgb8{0, 0, 255});  // hue 0 is blue
  CHECK(m[5] == Rgb8{255, 0, 0});  // CMY (0, 100, 100)
  CHECK(m.size() == 256);
}

TEST_CASE("unknown commands are counted by name and skipped to the next ESC") {
  Stream s;
  s.raw("\x1bQQ123abc\x1bZZ\x1bQQ");
  s.cmd("ML").i(9).cmd("LF").p(0, 0).cmd("LG").p(4000, 0);
  const Tek4125Decoder d = run(s.bytes);
  CHECK(d.report().unknownCommands == 3);
  CHECK(d.report().unknownByName.at("QQ") == 2);
  CHECK(d.report().unknownByName.at("ZZ") == 1);
  CHECK(at(d, 2000, 0) == 9);
  CHECK_THAT(d.report().summary(), Catch::Contains("unknown QQ: 2"));
}

TEST_CASE("commands cut short are malformed, parameters may be split by control characters") {
  Stream s;
  s.raw("\x1bLG\x1b");  // draw without a coordinate
  s.raw("\x1bML").raw("\r\n").i(12);  // a line break inside a command is ignored
  s.cmd("LF").p(0, 0).cmd("LG").p(4000, 0);
  s.raw("\x1bRP").i(10);  // the end arrives before the raster string
  const Tek4125Decoder d = run(s.bytes);
  CHECK(d.report().malformed == 2);
  CHECK(at(d, 2000, 0) == 12);
}

TEST_CASE("raster writes wrap at the viewport edge and XOR with ALU mode 7") {
  Stream s;
  s.cmd("RU").i(1).i(11).i(4);
  s.cmd("RS").p(10, 10).p(12, 11);  // a 3 x 2 viewport
  s.cmd("RH").p(0, 1);              // its top row
  // 6 pixels 1..6 at 4 bits: 24 bits = 4 characters.
  s.cmd("RP").i(6).i(4).raw(std::string{char(0x20 + 0x04), char(0x20 + 0x23), char(0x20 + 0x11),
                                        char(0x20 + 0x16)});
  s.cmd("RU").i(1).i(7).i(4);
  s.cmd("RR").p(10, 10).p(10, 10).i(15);
  // The wrap a row down (the default reading, raster-rows=up, wraps off the top).
  const Tek4125Decoder d = run(s.bytes, {}, {"raster-rows=down"});
  const IndexedImage& img = d.image();
  CHECK(img.at(10, 1023 - 11) == 1);
  CHECK(img.at(11, 1023 - 11) == 2);
  CHECK(img.at(12, 1023 - 11) == 3);
  CHECK(img.at(11, 1023 - 10) == 5);
  CHECK(img.at(12, 1023 - 10) == 6);
  CHECK(img.at(10, 1023 - 10) == (4 ^ 15));
  CHECK(img.at(13, 1023 - 11) == 0);  // nothing outside the viewport
  CHECK(d.report().malformed == 0);
}
