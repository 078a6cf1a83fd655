#pragma once
// A Tektronix 4100-series terminal emulator as a StreamDecoder: command
// bytes in, in any chunking; a framebuffer of colour-map indices (the
// profile's resolution) and the colour map out.
//
// It decodes everything Tek4125Driver emits under either form set (TM, TG,
// TB, RD, KI, RU, RS, RH, RP, RL, RR, ESC FF, ESC %!0/1, LV, and ESC ? for a
// DEL inside a parameter) and what a plotting program sends: LF/LG vectors,
// ML line index, LP..LG..LE panels filled with the MP pattern, 4010-style
// GS xy runs ended by US, the GKS driver's RL run-length writes, and the
// set-up, dialog-area and text-attribute commands gnuplot, PGPLOT, zebra,
// RAL-CGM and the RAL GKS driver send (accepted by name, nothing drawn).
// A byte-at-a-time state machine: nothing is buffered beyond the parameters
// of the command in hand (at most one 65535-entry integer array).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "devices/stream_decoder.hpp"
#include "devices/tek4125/tek4125_profile.hpp"
#include "devices/tek4125/tek4125_params.hpp"
#include "devices/tek4125/tek4125_readings.hpp"

namespace lattice::tek4125 {

class Tek4125Decoder final : public StreamDecoder {
 public:
  explicit Tek4125Decoder(const Tek4125Profile& profile, const Tek4125Readings& readings = {});
  void feed(std::span<const std::uint8_t> bytes) override;
  void finish() override;
  const IndexedImage& image() const override { return screen_; }
  const DecodeReport& report() const override { return report_; }
  const std::string& dialogText() const override { return dialog_; }
  bool inTekMode() const { return tekMode_; }

  // The power-up colour map (a reading: tek4125_readings.hpp).
  static Palette defaultColorMap(int entries, Tek4125PowerUpMap map = Tek4125PowerUpMap::Pgplot);

 private:
  enum class State : std::uint8_t { Ground, Esc, Percent, PercentBang, Name, Params, ParamsEsc, SkipToEsc };
  enum class Param : std::uint8_t { Int, IntArray, Xy, String, Raster };
  enum class Action : std::uint8_t { TM, TG, TB, RD, KI, RU, RS, RH, RP, RL, RR, LF, LG, ML, MP, LP, LE, Accept };
  struct Spec {
    char name[3];
    Action action;
    std::uint8_t required;  // parameters that must arrive; the rest may be cut short by ESC
    std::vector<Param> params;
  };
  static const std::vector<Spec>& commandTable();

  void feedByte(std::uint8_t c);
  void ground(std::uint8_t c);
  void escape(std::uint8_t c);
  void startCommand(const Spec& spec);
  void parameter(std::uint8_t c);
  void nextParameter();
  bool paramInProgress() const;
  void abandonCommand();  // an ESC or the end arrived inside a command
  void malformed();
  void execute();

  // Drawing, all clipped to the screen.
  void plot(int px, int py, int index);
  void line(int x0, int y0, int x1, int y1, int index);  // terminal coordinates
  void fillPanel();
  void rasterChar(std::uint8_t c);
  void writeAtBeam(int index, long count);  // raster pixels: right, wrapping up (or down) the viewport
  int pixelBits() const;  // bits a pixel in RP and RL, as the readings pack them
  void runLengthWrite();
  void setColor(int index, int c1, int c2, int c3);
  int pixelX(int x) const;
  int pixelY(int y) const;

  Tek4125Profile profile_;
  Tek4125Readings readings_;
  IndexedImage screen_;
  DecodeReport report_;
  int mask_;  // planes of surface 1 (all at power-up; RD may give it fewer)

  State state_ = State::Ground;
  bool tekMode_ = true;
  bool ignoreDel_ = false;   // KI1: raw DEL bytes are dropped; ESC ? stands for one
  bool graphMode_ = false;   // GS ... US vectors
  bool darkVector_ = false;  // next GS point moves rather than draws

  // The command in hand.
  const Spec* spec_ = nullptr;
  std::size_t paramIndex_ = 0;
  tek4125::IntReader int_;
  tek4125::XyReader xyReader_;
  tek4125::XyRegisters xy_;
  long remaining_ = -1;  // array entries or string chars still to come; -1 = count not read yet
  std::vector<int> ints_;
  std::vector<int> xys_;  // x0, y0, x1, y1, ...
  char name_[3] = {0, 0, 0};

  // Terminal state.
  int colorMode_ = 3;  // HLS at power-up
  int penX_ = 0, penY_ = 0;
  int lineIndex_ = 1;
  int fillPattern_ = 0;
  int alu_ = 11;
  int bitsPerPixel_;
  int vx0_ = 0, vy0_ = 0, vx1_ = 0, vy1_ = 0;  // pixel viewport, inclusive, Tek orientation
  int beamX_ = 0, beamY_ = 0;
  long rasterPixels_ = 0;  // pixels the RP in hand may still write
  unsigned rasterBits_ = 0;
  int rasterHeld_ = 0;
  bool panelOpen_ = false;
  bool panelBoundary_ = false;
  std::vector<int> panel_;  // terminal coordinates x0, y0, x1, y1, ...
  std::string dialog_;      // alphanumeric text: ANSI mode, and alpha mode in Tek mode
};

std::unique_ptr<Tek4125Decoder> makeTek4125Decoder(const Tek4125Profile& profile);

}  // namespace lattice::tek4125
