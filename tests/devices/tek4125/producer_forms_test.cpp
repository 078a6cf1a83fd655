// The forms other programs that drove 4100-series terminals send, built
// here byte by byte as each source builds them (docs/tek-sources.md): the
// RAL GKS 4200 driver's RL run-length writes, PGPLOT's set-up and RR erase,
// RAL-CGM's KI1 + ESC ? for DEL and its RD/TB set-up, and the readings a
// profile can switch (power-up colour map, RR and RH origins, surface planes).
#include <catch2/catch.hpp>

#include <string>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"
#include "tests/devices/tek4125/stream_builder.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

// Screen pixel (x, y), Tek orientation (y = 0 is the bottom row).
int px(const Tek4125Decoder& d, int x, int y) { return d.image().at(x, d.image().height - 1 - y); }

}  // namespace

TEST_CASE("RL rasters sent as the GKS driver sends them, bottom row first after one RS, stand upright") {
  // GK4TRO: RU -1 11 <planes>, RS upper-left then lower-right, then the
  // raster's rows from the bottom one up ("starting at base and working
  // upwards"), each row's runs as RL codes length * 2^bits + index, no RH.
  Stream s;
  s.cmd("RU").i(-1).i(11).i(4);
  s.cmd("RS").full(100, 209).full(109, 200);  // 10 x 10, corners in GKS's order
  // Image row r (0 = top): 4 pixels of index r + 1, then 6 of index 15 - r.
  for (int r = 9; r >= 0; --r) s.cmd("RL").i(2).i(4 * 16 + (r + 1)).i(6 * 16 + (15 - r));
  s.cmd("RL").i(1).i(15 * 16 + 3);  // 15 pixels: past the top row's end
  const auto up = run(s.bytes), flipped = run(s.bytes, {}, {"raster-rows=down"});
  for (const Tek4125Decoder* d : {&up, &flipped}) {
    CHECK(d->report().malformed == 0);
    CHECK(d->report().unknownCommands == 0);
  }
  // raster-rows=up (the default): the first row sent is the bottom one.
  for (int r = 0; r < 10; ++r) {
    INFO("image row " << r);
    CHECK(px(up, 100, 209 - r) == r + 1);
    CHECK(px(up, 103, 209 - r) == r + 1);
    CHECK(px(up, 104, 209 - r) == 15 - r);
    CHECK(px(up, 109, 209 - r) == 15 - r);
    // raster-rows=down: the old assumption shows the picture upside down.
    CHECK(px(flipped, 100, 200 + r) == r + 1);
    CHECK(px(flipped, 109, 200 + r) == 15 - r);
  }
  // The last code ran off the viewport's top (up) or bottom (down): nothing
  // is drawn outside it, and the picture's rows stay as they were.
  CHECK(px(up, 100, 210) == 0);
  CHECK(px(flipped, 100, 199) == 0);
  CHECK(px(up, 110, 209) == 0);  // nothing right of the viewport
}

TEST_CASE("RL at 8 bits wraps a run across the viewport's edge, a row up or (raster-rows=down) a row down") {
  Stream s;
  s.cmd("RU").i(1).i(11).i(8);
  s.cmd("RS").full(0, 0).full(1279, 1023);
  s.cmd("RH").full(1270, 500);
  s.cmd("RL").i(2).i(12 * 256 + 200).i(255 * 256 + 9);
  s.cmd("RH").full(0, 0);
  s.cmd("RL").i(1).i(65535);  // the largest code: 255 pixels of index 255
  const auto up = run(s.bytes), d = run(s.bytes, {}, {"raster-rows=down"});
  CHECK(up.report().malformed == 0);
  CHECK(d.report().malformed == 0);
  CHECK(px(up, 1279, 500) == 200);
  CHECK(px(up, 1, 501) == 200);  // wrapped to the viewport's left edge, a row up
  CHECK(px(up, 2, 501) == 9);
  CHECK(px(up, 1, 499) == 0);
  CHECK(px(d, 1279, 500) == 200);
  CHECK(px(d, 1, 499) == 200);  // the other reading: a row down
  CHECK(px(d, 2, 499) == 9);
  CHECK(px(up, 254, 0) == 255);
  CHECK(px(d, 254, 0) == 255);
}

TEST_CASE("RL codes split by RU's bits, or (pixel-bits=surface) by surface 1's planes") {
  // No source writes fewer bits than its surface has planes (zebra: RU 0 11 4
  // on 4 planes; the GKS driver: RD 1 N, RU -1 11 N): RD 1 8 then RU 4 bits.
  Stream s;
  s.cmd("RD").i(1).i(8).cmd("RU").i(1).i(11).i(4);
  s.cmd("RS").full(0, 0).full(1279, 1023).cmd("RH").full(0, 0);
  s.cmd("RL").i(1).i(2 * 256 + 7);  // 32 pixels at 4 bits, 2 at 8
  const auto ru = run(s.bytes), planes = run(s.bytes, {}, {"pixel-bits=surface"});
  CHECK(px(ru, 31, 0) == 7);
  CHECK(px(ru, 32, 0) == 0);
  CHECK(px(planes, 1, 0) == 7);
  CHECK(px(planes, 2, 0) == 0);
}

TEST_CASE("after KI1 a raw DEL is dropped and ESC ? stands for it inside a parameter") {
  // RAL-CGM cgmtek.h: TEKCHOUT sends 0x7F as ESC ?. In (x, 127) Lo-Y is 31:
  // a DEL; in (1023, 127) Extra is 0x6F.
  auto escaped = [](Stream& s, int x, int y) {
    Bytes b;
    XyEncoder fresh;
    fresh.append(b, x, y);
    for (std::uint8_t c : b) {
      if (c == 0x7F) s.raw("\x1b?");
      else s.bytes.push_back(c);
      s.bytes.push_back(0x7F);  // padding a line might add: ignored after KI1
    }
  };
  Stream s;
  s.cmd("KI").i(1).cmd("ML").i(1).cmd("LF");
  escaped(s, 0, 127);
  s.cmd("LG");
  escaped(s, 1023, 127);
  const auto d = run(s.bytes);
  CHECK(d.report().malformed == 0);
  CHECK(px(d, 0, 127 * 1280 / 4096) == 1);
  CHECK(px(d, 1023 * 1280 / 4096, 127 * 1280 / 4096) == 1);
  // Without KI1, DEL is data (gnuplot's tek40xx sends it raw as a Lo-Y).
  Stream t;
  t.cmd("ML").i(1).cmd("LF").full(0, 127).cmd("LG").full(1023, 127);
  const auto e = run(t.bytes);
  CHECK(e.report().malformed == 0);
  CHECK(px(e, 0, 127 * 1280 / 4096) == 1);
  CHECK(px(e, 1023 * 1280 / 4096, 127 * 1280 / 4096) == 1);
}

TEST_CASE("RD gives surface 1 its planes, fewer planes mask the indices drawn") {
  Stream s;
  s.cmd("RD").i(1).i(4);  // surface 1 owns 4 of the 8 planes
  s.cmd("RU").i(1).i(11).i(8).cmd("RS").full(0, 0).full(1279, 1023);
  s.cmd("RR").full(10, 10).full(11, 11).i(0x35);
  auto d = run(s.bytes);
  CHECK(d.report().malformed == 0);
  CHECK(px(d, 10, 10) == 0x5);
  // A terminal whose surface 1 starts with 4 planes masks too, until RD says 8.
  const std::vector<std::string> fourPlaneSurface = {"surface-planes=4"};
  Stream t;
  t.cmd("RR").full(10, 10).full(11, 11).i(0x35);
  CHECK(px(run(t.bytes, {}, fourPlaneSurface), 10, 10) == 0x5);
  Stream u;
  u.cmd("RD").i(1).i(8).cmd("RR").full(10, 10).full(11, 11).i(0x35);
  CHECK(px(run(u.bytes, {}, fourPlaneSurface), 10, 10) == 0x35);
}

TEST_CASE("TB sets the colour of entry 0, in the colour mode in force") {
  Stream s;
  s.cmd("TM").i(1).i(1).i(1).cmd("TB").i(0).i(50).i(100);
  const auto d = run(s.bytes);
  CHECK(d.report().malformed == 0);
  CHECK(d.image().colormap[0] == Rgb8{0, 128, 255});
}

TEST_CASE("the power-up colour map follows PGPLOT's table or, as a reading, RAL-CGM's") {
  const Palette pgplot = Tek4125Decoder::defaultColorMap(256, Tek4125PowerUpMap::Pgplot);
  const Palette ral = Tek4125Decoder::defaultColorMap(256, Tek4125PowerUpMap::RalCgm);
  CHECK(pgplot[5] == Rgb8{0, 255, 255});
  CHECK(pgplot[6] == Rgb8{255, 0, 255});
  CHECK(pgplot[7] == Rgb8{255, 255, 0});
  CHECK(ral[5] == Rgb8{255, 255, 0});
  CHECK(ral[6] == Rgb8{0, 255, 255});
  CHECK(ral[7] == Rgb8{255, 0, 255});
  CHECK(pgplot[1] == ral[1]);
  CHECK(pgplot[16] == Rgb8{0, 0, 0});
  CHECK(Tek4125Decoder(Tek4125Profile{}, readingsOf({"power-up-map=ral-cgm"})).image().colormap[5] == Rgb8{255, 255, 0});
}

TEST_CASE("PGPLOT's, zebra's, RAL-CGM's and the GKS driver's set-up sequences are accepted whole") {
  Stream s;
  // PGPLOT tkdriv.f, begin picture: RU1;6, LL2, RS, TM111, TG14 per entry, RR erase, ML1.
  s.raw("\x1b%!0").raw("\x1bRU1;6").raw("\x1bLL2").cmd("RS").full(0, 0).full(639, 479).raw("\x1bTM111");
  s.cmd("TG").i(1).i(4).i(3).i(0).i(100).i(0);
  s.cmd("RR").full(0, 0).full(639, 479).i(3).raw("\x1bML1");
  // zebra dev_4107.c tek_open: NQ, RW, SK, SV.
  s.cmd("NQ").i(32767).cmd("RW").full(0, 0).full(639, 479).cmd("SK").i(-1).raw("\x1bSV00");
  // RAL-CGM TEKinit: KI1, TB000, MB00, RE0, TM111, NT, NC, KT2, ML1, MV0, RD1 4, RV, RW.
  s.raw("\x1bKI1\x1bTB000\x1bMB00\x1bRE0\x1bTM111\x1bNT1=\x1bNC=0\x1bKT2\x1bML1\x1bMV0");
  s.cmd("RD").i(1).i(8).cmd("RV").full(0, 0).full(4095, 3071).cmd("RW").full(0, 0).full(4095, 3071);
  // GKS GK4TID: KE0, KT2, MB00, RE0, TB000, KA1, RF2, MG1.
  s.raw("\x1bKE0\x1bKT2\x1bMB00\x1bRE0\x1bTB000\x1bKA1\x1bRF2\x1bMG1");
  // BRL-CAD dm-tek4109.c T49_open: NF1, MC, LL, KI0, IJ5:, TCK4C2F4, ML2; and KC.
  s.raw("\x1bNF1\x1bMCA>B8:\x1bLLA>\x1bKI0\x1bIJ5:\x1bTCK4C2F4\x1bML2\x1bKC");
  // zebra segments: SO 1, SC, QA1.
  s.raw("\x1bSO1\x1bSC\x1bQA1");
  const auto d = run(s.bytes);
  CHECK(d.report().malformed == 0);
  CHECK(d.report().unknownCommands == 0);
  CHECK(px(d, 0, 0) == 3);    // PGPLOT's erase in index 3
  CHECK(px(d, 639, 479) == 3);
  CHECK(px(d, 640, 479) == 0);
  CHECK(d.image().colormap[3] == Rgb8{0, 255, 0});
}

TEST_CASE("RR and RH follow the origin readings") {
  Stream s;
  s.cmd("RS").full(100, 100).full(199, 199).cmd("RR").full(0, 0).full(1, 1).i(4);
  s.cmd("RU").i(1).i(11).i(4).cmd("RH").full(10, 10).cmd("RP").i(1).i(1).raw("\x50");  // index 12
  const auto screen = run(s.bytes);
  CHECK(px(screen, 0, 0) == 4);
  CHECK(px(screen, 110, 110) == 12);
  const auto viewport = run(s.bytes, {}, {"rr-origin=viewport", "rh-origin=screen"});
  CHECK(px(viewport, 0, 0) == 0);
  CHECK(px(viewport, 100, 100) == 4);
  // RH from the screen puts the beam left of and below the viewport: RP
  // writes nothing there, as nothing outside the viewport is drawn.
  CHECK(px(viewport, 10, 10) == 0);
  CHECK(px(viewport, 110, 110) == 0);
}
