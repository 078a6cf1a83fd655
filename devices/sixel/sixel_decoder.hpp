#pragma once
// The sixel emulator: a byte-at-a-time parser of DCS ... q sixel strings
// (sixel_forms.hpp) drawing into a canvas of register numbers, with the
// registers' colours as the colour map. Chunking never matters: all state
// lives in the object between feed() calls.
//
// Method and tunables (docs/sixel.md has the account, docs/sixel-sources.md
// the sources):
//  * As xterm's parse_sixel: `#Pc` alone selects, `#Pc;Pu;x;y;z` defines
//    (RGB percent, or HLS with hue 0 = blue as DEC's); a register past the
//    last wraps around; the current register starts at 3; `"` raster
//    attributes declare the size; unless P2 = 1 the declared area is filled
//    with register 0 at the first sixel; later sixels overwrite earlier ones.
//  * Pixels are sixel pixels: the aspect (P1, Pan:Pad) is read and counted
//    but not applied, so our own 1:1 streams show at their size.
//  * Size caps: the canvas is at most the profile's width x height (xterm's
//    maxGraphicSize); a declared size beyond it is clipped and counted as
//    malformed, sixels beyond it are not drawn. It grows as rows are drawn,
//    so a small stream costs little memory. Numbers saturate at kMaxNumber;
//    a DCS has at most kMaxParams parameters counted.
//  * Work: a sixel costs 6 units a visible column (a repeat only its visible
//    columns), the background fill one a pixel, charged against
//    kPixelWorkBudget (devices/work_budget.hpp) before drawing.
//  * Never throws on content: anything else is skipped and counted.
//    Several images in one stream are drawn over one another from (0, 0).
#include <string>
#include <vector>

#include "devices/sixel/sixel_profile.hpp"
#include "devices/stream_decoder.hpp"

namespace lattice::sixel {

class SixelDecoder final : public StreamDecoder {
 public:
  static constexpr std::uint32_t kMaxNumber = 999999;
  static constexpr std::size_t kMaxParams = 16;
  static constexpr std::size_t kMaxUnknownNames = 64;

  explicit SixelDecoder(SixelProfile profile = {});

  void feed(std::span<const std::uint8_t> bytes) override;
  void finish() override;
  // The canvas cropped to what was declared or drawn (at least 1x1).
  const IndexedImage& image() const override;
  const DecodeReport& report() const override { return report_; }

  int images() const { return images_; }

 private:
  enum class State { Ground, Escape, Csi, DcsParams, Sixel, SixelEscape, Ignore, IgnoreEscape };

  void consume(std::uint8_t byte);
  void ground(std::uint8_t byte);
  void escape(std::uint8_t byte);
  void dcsParams(std::uint8_t byte);
  void sixel(std::uint8_t byte);
  void startImage();
  void endImage();
  bool finishPending(std::uint8_t next);  // true: `next` was the repeat's sixel
  void defineOrSelect();
  void raster();
  void draw(std::uint8_t bits, std::uint32_t count);
  void fillBackground();
  void ensureRows(int rows);
  void unknown(const std::string& name);
  void stray();

  SixelProfile profile_;
  DecodeReport report_;
  State state_ = State::Ground;
  bool inStrayText_ = false;

  // Parameters of the DCS or of the pending sixel command.
  std::vector<std::uint32_t> params_;
  char pending_ = 0;  // '#', '"', '!' while its parameters arrive

  // The image being drawn.
  int background_ = 0;  // P2
  bool filled_ = false;
  int declaredWidth_ = 0, declaredHeight_ = 0;
  int col_ = 0, row_ = 0;
  int register_ = 3;
  int images_ = 0;

  std::vector<Rgb8> registers_;
  std::vector<PaletteIndex> pixels_;  // rows of profile_.width, grown as needed
  int rows_ = 0;                      // rows allocated
  int extentWidth_ = 0, extentHeight_ = 0;
  mutable IndexedImage view_;
  mutable bool dirty_ = true;
};

}  // namespace lattice::sixel
