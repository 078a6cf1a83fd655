#pragma once
// The 4014 emulator: a byte-at-a-time parser of the Tek 4010/4014 graphics
// language, as xterm's Tek window (`xterm -t`, Tekproc.c) accepts it, onto a
// monochrome screen of 1024x780 or 4096x3120 pixels (the profile's address
// bits): index 0 dark, 1 lit. Chunking never matters: every state lives in the
// object between feed() calls. docs/tek4014.md lists what it does and does
// not do; docs/tek4014-sources.md cites each form.
//
// Method and tunables:
//  - Modes: alpha (US), graph (GS: the first address after GS moves the
//    beam, the next ones draw vectors; GS BEL starts with the pen down),
//    point plot (FS: each address is a dot), special point plot (ESC FS: an
//    intensity byte, ignored, then an address), incremental plot (RS: SP pen
//    up, P pen down, A/E/D/F/B/J/H/I one 12-bit unit east, north-east, ...).
//  - Every address is assembled as tek4014_address.hpp says, in 12-bit units;
//    a pixel is coord >> 2 on the 10-bit screen, coord on the 12-bit one.
//  - A control byte inside an address abandons it (counted as malformed)
//    and then acts; bytes 0x80..0xFF are ignored where an address could start
//    and read as Lo Y inside one, as xterm does.
//  - ESC FF erases; ESC 8..; (character size), ESC ` .. w (beam and line
//    style), ESC ENQ, ESC ETB, ESC SUB, ESC CAN, ESC SO/SI, ESC ETX are
//    recognised; an OSC (ESC ] ... BEL) is skipped, at most kMaxOsc bytes.
//  - Not drawn: alpha text (counted once per run as an unknown command, named
//    in the report), and line styles other than solid are drawn solid (named
//    in the report). Alpha cursor motions (LF, BS, HT, VT, text) do not move
//    the beam; CR puts it at x = 0.
//  - The screen is a Tek4014Screen (tek4014_screen.hpp: bitmaps, a vector
//    drawn as runs of straight or diagonal steps, the pixels
//    devices::drawLine lights); image() makes the IndexedImage from it when
//    the screen changed since the last call.
//  - Bounded: the screen is the only allocation (and the picture image()
//    returns); each vector is charged the pixels it lights on the screen
//    (a dot 1), each erase the screen's pixels, against kPixelWorkBudget
//    (devices/work_budget.hpp) before it is drawn.
#include <cstdint>

#include "devices/stream_decoder.hpp"
#include "devices/tek4014/tek4014_address.hpp"
#include "devices/tek4014/tek4014_profile.hpp"
#include "devices/tek4014/tek4014_screen.hpp"

namespace lattice::tek4014 {

class Tek4014Decoder final : public StreamDecoder {
 public:
  static constexpr int kMaxOsc = 512;  // xterm's own OSC buffer in Tek mode

  explicit Tek4014Decoder(Tek4014Profile profile = {});

  void feed(std::span<const std::uint8_t> bytes) override;
  void finish() override;
  const IndexedImage& image() const override;
  const DecodeReport& report() const override { return report_; }

  // State a test may inspect (12-bit units).
  int beamX() const { return beamX_; }
  int beamY() const { return beamY_; }
  int lineStyle() const { return lineStyle_; }

 private:
  enum class Mode { Alpha, Graph, Point, SpecialPoint, Incremental };
  enum class Escape { None, Pending, Osc };

  void consume(std::uint8_t b);
  void control(std::uint8_t b);
  void escaped(std::uint8_t b);
  void graphic(std::uint8_t b);
  void incremental(std::uint8_t b);
  void enter(Mode mode);
  void abandonAddress();
  void unknown(const std::string& name);
  void page();
  void moveOrDraw(int x, int y, bool draw);

  Tek4014Profile profile_;
  Tek4014Screen screen_;
  mutable IndexedImage picture_;  // made from screen_ by image()
  mutable bool stale_ = true;     // screen_ changed since picture_ was made
  DecodeReport report_;

  Mode mode_ = Mode::Alpha;
  Escape escape_ = Escape::None;
  int oscBytes_ = 0;
  bool bypass_ = false;
  bool afterGs_ = false;        // the byte after GS: BEL there puts the pen down
  bool penDown_ = false;
  bool haveIntensity_ = false;  // special point plot: the intensity byte came
  bool inText_ = false;
  AddressAssembler address_;
  int beamX_ = 0, beamY_ = 0;
  int lineStyle_ = 0;
};

}  // namespace lattice::tek4014
