#include "devices/tek4125/tek4125_decoder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>

#include "devices/canvas.hpp"
#include "devices/gun_percent.hpp"
#include "devices/tek_hls.hpp"
#include "devices/work_budget.hpp"
#include "foundation/rounding.hpp"

namespace lattice::tek4125 {

namespace {

constexpr std::uint8_t kEsc = 0x1B, kFF = 0x0C, kGS = 0x1D, kUS = 0x1F, kCR = 0x0D, kDel = 0x7F;
constexpr std::size_t kMaxPanelPoints = 65536;  // bounds the fill work a stream can ask for

}  // namespace

const std::vector<Tek4125Decoder::Spec>& Tek4125Decoder::commandTable() {
  using P = Param;
  static const std::vector<Spec> table = {
      {"TM", Action::TM, 1, {P::Int, P::Int, P::Int}},    // colour mode, overlay, grey
      {"TG", Action::TG, 2, {P::Int, P::IntArray}},       // surface, (index c1 c2 c3)...
      {"TB", Action::TB, 3, {P::Int, P::Int, P::Int}},    // background colour
      {"RD", Action::RD, 1, {P::IntArray}},               // planes of surface 1, 2, ...
      {"KI", Action::KI, 1, {P::Int}},                    // 1: ignore DEL
      {"RU", Action::RU, 3, {P::Int, P::Int, P::Int}},    // surface, ALU mode, bits per pixel
      {"RS", Action::RS, 2, {P::Xy, P::Xy}},              // pixel viewport corners
      {"RH", Action::RH, 1, {P::Xy}},                     // beam position in the viewport
      {"RP", Action::RP, 2, {P::Int, P::Raster}},         // pixel count, packed string
      {"RL", Action::RL, 1, {P::IntArray}},               // run codes: length * 2^bits + index
      {"RR", Action::RR, 3, {P::Xy, P::Xy, P::Int}},      // rectangle corners, index
      {"LF", Action::LF, 1, {P::Xy}},                     // move
      {"LG", Action::LG, 1, {P::Xy}},                     // draw (or panel point)
      {"ML", Action::ML, 1, {P::Int}},                    // line index
      {"MP", Action::MP, 1, {P::Int}},                    // fill pattern
      {"LP", Action::LP, 2, {P::Xy, P::Int}},             // begin panel, boundary flag
      {"LE", Action::LE, 0, {}},                          // end panel
      // Dialog area, text and housekeeping: parsed so they resynchronise
      // nothing, but with no visible effect on the graphics here.
      {"KA", Action::Accept, 1, {P::Int}},  // dialog area enable
      {"LV", Action::Accept, 1, {P::Int}},  // dialog area visibility
      {"LL", Action::Accept, 1, {P::Int}},  // dialog area lines
      {"LB", Action::Accept, 1, {P::Int}},  // dialog area buffer size
      {"LZ", Action::Accept, 0, {}},        // clear dialog area
      {"MN", Action::Accept, 1, {P::Int}},  // text path
      {"MC", Action::Accept, 2, {P::Int, P::Int, P::Int}},  // text size (gnuplot sends two)
      {"MQ", Action::Accept, 1, {P::Int}},                  // text precision
      {"MT", Action::Accept, 1, {P::Int}},                  // text index
      {"MG", Action::Accept, 1, {P::Int}},                  // text write mode
      {"MV", Action::Accept, 1, {P::Int}},                  // line style
      {"MM", Action::Accept, 1, {P::Int}},                  // marker type
      {"MR", Action::Accept, 2, {P::Int, P::Int}},          // text rotation (a real)
      {"RK", Action::Accept, 1, {P::Int}},                  // renew view
      {"SK", Action::Accept, 1, {P::Int}},                  // delete segment
      {"LH", Action::Accept, 1, {P::Xy}},                   // marker (not drawn)
      {"LT", Action::Accept, 1, {P::String}},               // graphic text (no font: not drawn)
      // Set-up commands of PGPLOT, zebra, RAL-CGM, the RAL GKS driver and
      // BRL-CAD (docs/tek-sources.md).
      {"MB", Action::Accept, 2, {P::Int, P::Int}},  // background indices (text)
      {"RE", Action::Accept, 1, {P::Int}},          // view border
      {"RF", Action::Accept, 1, {P::Int}},          // fix-up level
      {"RV", Action::Accept, 2, {P::Xy, P::Xy}},    // viewport (views are not emulated)
      {"RW", Action::Accept, 2, {P::Xy, P::Xy}},    // window (not applied: docs/tek4125.md)
      {"KN", Action::Accept, 1, {P::Int}},          // renew view
      {"KE", Action::Accept, 1, {P::Int}},          // echo
      {"KT", Action::Accept, 1, {P::Int}},          // error threshold
      {"NT", Action::Accept, 1, {P::IntArray}},     // end-of-line string
      {"NC", Action::Accept, 2, {P::Int, P::Int}},  // end-of-message characters
      {"NQ", Action::Accept, 1, {P::Int}},          // queue size
      {"SV", Action::Accept, 2, {P::Int, P::Int}},  // segment visibility
      {"SO", Action::Accept, 1, {P::Int}},          // begin segment (zebra)
      {"SC", Action::Accept, 0, {}},                // end segment
      {"QA", Action::Accept, 1, {P::Int}},          // copy size
      {"NF", Action::Accept, 1, {P::Int}},          // flagging (BRL-CAD dm-tek4109.c)
      {"KC", Action::Accept, 0, {}},                // cancel crosshairs
      {"TC", Action::Accept, 3, {P::Int, P::Int, P::Int}},  // GIN cursor colour
      {"IJ", Action::Accept, 2, {P::Int, P::Int}},          // GIN cursor speed
  };
  return table;
}

Palette Tek4125Decoder::defaultColorMap(int entries, Tek4125PowerUpMap which) {
  // Percent a gun. PGPLOT drivers/tkdriv.f (CTABLE) and RAL-CGM cgmtek.h
  // (TEKdftcoltab) agree but for entries 5..7 and a few 50-versus-51s.
  static const int pgplot[16][3] = {{0, 0, 0},    {100, 100, 100}, {100, 0, 0},  {0, 100, 0},
                                    {0, 0, 100},  {0, 100, 100},   {100, 0, 100}, {100, 100, 0},
                                    {100, 50, 0}, {50, 100, 0},    {0, 100, 50},  {0, 50, 100},
                                    {50, 0, 100}, {100, 0, 50},    {33, 33, 33},  {67, 67, 67}};
  static const int ralCgm[16][3] = {{0, 0, 0},    {100, 100, 100}, {100, 0, 0},  {0, 100, 0},
                                    {0, 0, 100},  {100, 100, 0},   {0, 100, 100}, {100, 0, 100},
                                    {100, 50, 0}, {51, 100, 0},    {0, 100, 51},  {0, 51, 100},
                                    {50, 0, 100}, {100, 0, 50},    {33, 33, 33},  {67, 67, 67}};
  const auto& table = which == Tek4125PowerUpMap::Pgplot ? pgplot : ralCgm;
  Palette map(static_cast<std::size_t>(entries));
  for (int i = 0; i < entries && i < 16; ++i)
    map[static_cast<std::size_t>(i)] = Rgb8{devices::eightOfPercent(table[i][0]), devices::eightOfPercent(table[i][1]),
                                            devices::eightOfPercent(table[i][2])};
  return map;
}

Tek4125Decoder::Tek4125Decoder(const Tek4125Profile& profile, const Tek4125Readings& readings)
    : profile_(profile), readings_(readings), mask_(0), bitsPerPixel_(profile.planes) {
  profile_.validate();
  const int surface = readings_.surfacePlanes > 0 ? std::min(readings_.surfacePlanes, profile_.planes) : profile_.planes;
  mask_ = (1 << surface) - 1;
  screen_ = IndexedImage(profile_.width, profile_.height, 0);
  screen_.colormap = defaultColorMap(profile_.colorMapSize(), readings_.powerUpMap);
  vx1_ = profile_.width - 1;
  vy1_ = profile_.height - 1;
}

void Tek4125Decoder::feed(std::span<const std::uint8_t> bytes) {
  for (std::uint8_t c : bytes) feedByte(c);
  report_.bytes += bytes.size();
}

void Tek4125Decoder::finish() {
  if (state_ == State::Params) abandonCommand();
  else if (state_ == State::ParamsEsc) {  // the command ends, the ESC is cut short
    abandonCommand();
    malformed();
  }
  else if (state_ == State::Esc || state_ == State::Percent || state_ == State::PercentBang ||
           state_ == State::Name)
    malformed();
  if (graphMode_ && xyReader_.started()) malformed();
  xyReader_.reset();
  state_ = State::Ground;
}

void Tek4125Decoder::malformed() { ++report_.malformed; }

void Tek4125Decoder::feedByte(std::uint8_t c) {
  if (c == kDel && ignoreDel_) return;  // KI1: DEL is padding, ESC ? stands for it
  if (c == kEsc) {
    if (state_ == State::Params) {
      state_ = State::ParamsEsc;  // ESC ? continues the command with a DEL; anything else ends it
      return;
    }
    if (state_ == State::ParamsEsc) abandonCommand();
    else if (state_ == State::Percent || state_ == State::PercentBang || state_ == State::Name) malformed();
    state_ = State::Esc;
    return;
  }
  switch (state_) {
    case State::Ground: return ground(c);
    case State::Esc: return escape(c);
    case State::Percent:
      if (c == '!') {
        state_ = State::PercentBang;
        int_.reset();
      } else if (c >= 0x20) {
        malformed();
        state_ = State::SkipToEsc;
      }
      return;
    case State::PercentBang: {
      if (c < 0x20) return;
      const tek4125::ReadStatus s = int_.feed(c);
      if (s == tek4125::ReadStatus::More) return;
      state_ = State::Ground;
      if (s == tek4125::ReadStatus::Bad) return malformed();
      const int mode = int_.value();
      if (mode == 0 || mode == 1) {
        tekMode_ = mode == 0;
        graphMode_ = false;
        ++report_.commands;
      } else {
        ++report_.unknownCommands;
        ++report_.unknownByName["%!" + std::to_string(mode)];
      }
      return;
    }
    case State::Name:
      if (c < 0x20) return;  // control characters inside a command are ignored
      if (c < 'A' || c > 'Z') {
        malformed();
        state_ = State::SkipToEsc;
        return;
      }
      name_[1] = static_cast<char>(c);
      for (const Spec& spec : commandTable())
        if (spec.name[0] == name_[0] && spec.name[1] == name_[1]) return startCommand(spec);
      ++report_.unknownCommands;
      ++report_.unknownByName[std::string(name_, 2)];
      state_ = State::SkipToEsc;  // its parameters are unknown: resynchronise at the next ESC
      return;
    case State::Params: return parameter(c);
    case State::ParamsEsc:
      if (c == '?') {  // RAL-CGM cgmtek.h sends DEL as ESC ?
        state_ = State::Params;
        return parameter(kDel);
      }
      abandonCommand();
      state_ = State::Esc;
      return escape(c);
    case State::SkipToEsc: return;
  }
}

void Tek4125Decoder::ground(std::uint8_t c) {
  const bool text = (c >= 0x20 && c < kDel) || c == '\n' || c == kCR;
  if (!tekMode_) {  // ANSI mode: text for the dialog area, not graphics
    if (text) appendDialogText(dialog_, c);
    return;
  }
  if (!graphMode_ && text) appendDialogText(dialog_, c);  // alpha mode: the dialog area's text
  if (c == kGS) {
    graphMode_ = true;
    darkVector_ = true;
    xyReader_.reset();
    return;
  }
  if (c == kUS || c == kCR) {  // back to alpha mode
    graphMode_ = false;
    xyReader_.reset();
    return;
  }
  if (!graphMode_ || c < 0x20) return;  // alpha text is not drawn; other controls ignored
  const tek4125::ReadStatus s = xyReader_.feed(c, xy_);
  if (s != tek4125::ReadStatus::Done) return;
  xyReader_.reset();
  if (darkVector_) darkVector_ = false;
  else line(penX_, penY_, xy_.x(), xy_.y(), lineIndex_);
  penX_ = xy_.x();
  penY_ = xy_.y();
}

void Tek4125Decoder::escape(std::uint8_t c) {
  if (c == '?') {  // a DEL outside a command (a vector's Lo-Y or Extra)
    state_ = State::Ground;
    return ground(kDel);
  }
  if (c == '%') {
    state_ = State::Percent;
    return;
  }
  if (!tekMode_) {  // ANSI sequences are not ours: skip to the next ESC
    if (c >= 0x20) state_ = State::SkipToEsc;
    return;
  }
  if (c == kFF) {  // page clear, back to alpha mode
    if (chargePixelWork(report_, screen_.pixels.size()))
      std::fill(screen_.pixels.begin(), screen_.pixels.end(), PaletteIndex{0});
    graphMode_ = false;
    ++report_.commands;
    state_ = State::Ground;
    return;
  }
  if (c < 0x20) return;  // ignored, the ESC still stands
  if (c >= 'A' && c <= 'Z') {
    name_[0] = static_cast<char>(c);
    state_ = State::Name;
    return;
  }
  malformed();
  state_ = State::SkipToEsc;
}

void Tek4125Decoder::startCommand(const Spec& spec) {
  spec_ = &spec;
  paramIndex_ = 0;
  ints_.clear();
  xys_.clear();
  int_.reset();
  xyReader_.reset();
  remaining_ = -1;
  state_ = State::Params;
  if (spec.params.empty()) execute();
}

bool Tek4125Decoder::paramInProgress() const {
  return int_.started() || xyReader_.started() || remaining_ >= 0;
}

void Tek4125Decoder::abandonCommand() {
  if (paramIndex_ >= spec_->required && !paramInProgress()) {
    execute();
  } else {
    malformed();
    state_ = State::Ground;
  }
}

void Tek4125Decoder::nextParameter() {
  int_.reset();
  xyReader_.reset();
  remaining_ = -1;
  if (++paramIndex_ == spec_->params.size()) execute();
}

void Tek4125Decoder::parameter(std::uint8_t c) {
  const Param p = spec_->params[paramIndex_];
  const bool inBody = remaining_ >= 0;
  if (p == Param::String && inBody) {  // string characters are taken raw
    if (--remaining_ == 0) nextParameter();
    return;
  }
  if (c < 0x20) return;  // the terminal ignores control characters between parameter bytes
  if (p == Param::Raster && inBody) {
    rasterChar(c);
    if (--remaining_ == 0) nextParameter();
    return;
  }
  if (p == Param::Xy) {
    const tek4125::ReadStatus s = xyReader_.feed(c, xy_);
    if (s == tek4125::ReadStatus::Done) {
      xys_.push_back(xy_.x());
      xys_.push_back(xy_.y());
      nextParameter();
    } else if (s == tek4125::ReadStatus::Bad) {
      malformed();
      state_ = State::SkipToEsc;
    }
    return;
  }
  const tek4125::ReadStatus s = int_.feed(c);
  if (s == tek4125::ReadStatus::More) return;
  if (s == tek4125::ReadStatus::Bad) {
    malformed();
    state_ = State::SkipToEsc;
    return;
  }
  const int v = int_.value();
  int_.reset();
  if (p == Param::Int) {
    ints_.push_back(v);
    return nextParameter();
  }
  if (inBody) {  // an array element
    ints_.push_back(v);
    if (--remaining_ == 0) nextParameter();
    return;
  }
  // A count: of array entries, string characters or raster characters.
  if (v < 0) {
    malformed();
    state_ = State::SkipToEsc;
    return;
  }
  if (p == Param::Raster) {
    // The pixel count came before; start the raster write now, so pixels
    // stream onto the screen as their characters arrive.
    rasterPixels_ = ints_.empty() ? 0 : std::max(ints_.back(), 0);
    rasterBits_ = 0;
    rasterHeld_ = 0;
  }
  if (p == Param::IntArray) ints_.push_back(v);
  if (v == 0) return nextParameter();
  remaining_ = v;
}

int Tek4125Decoder::pixelX(int x) const { return x * profile_.width / 4096; }
// The same scale vertically, so terminal space keeps its aspect ratio; y
// beyond the screen's top (above 3276 on a 1280x1024 screen) is clipped.
int Tek4125Decoder::pixelY(int y) const { return y * profile_.width / 4096; }

void Tek4125Decoder::plot(int px, int py, int index) {
  PaletteIndex* p = devices::pixelAt(screen_, px, py);
  if (p == nullptr) return;
  const int v = index & mask_;
  *p = static_cast<PaletteIndex>(alu_ == 7 ? (*p ^ v) : v);
}

// Vectors overwrite: the ALU mode belongs to pixel operations.
void Tek4125Decoder::line(int x0, int y0, int x1, int y1, int index) {
  const int px0 = pixelX(x0), py0 = pixelY(y0), px1 = pixelX(x1), py1 = pixelY(y1);
  if (!chargePixelWork(report_, devices::lineWork(screen_, px0, py0, px1, py1))) return;
  devices::drawLine(screen_, px0, py0, px1, py1, static_cast<PaletteIndex>(index & mask_));
}

// Patterns above 0 are drawn solid in the line index (no pattern bitmaps
// are emulated); the fill uses the same scale as vectors.
void Tek4125Decoder::fillPanel() {
  panelOpen_ = false;
  const std::size_t n = panel_.size() / 2;
  const int index = fillPattern_ <= 0 ? -fillPattern_ : lineIndex_;
  const double scale = profile_.width / 4096.0;
  std::vector<double> points(panel_.size());
  for (std::size_t i = 0; i < panel_.size(); ++i) points[i] = panel_[i] * scale;
  if (chargePixelWork(report_, devices::fillPolygonWork(screen_, points)))
    devices::fillPolygon(screen_, points, static_cast<PaletteIndex>(index & mask_));
  if (panelBoundary_ && n >= 2)
    for (std::size_t i = 0, j = n - 1; i < n; j = i++)
      line(panel_[2 * j], panel_[2 * j + 1], panel_[2 * i], panel_[2 * i + 1], lineIndex_);
  panel_.clear();
}

void Tek4125Decoder::rasterChar(std::uint8_t c) {
  if (c > 0x5F) return malformed();  // not a 6-bit group character
  rasterBits_ = (rasterBits_ << 6 | (c - 0x20u)) & 0xFFFu;  // at most 8 + 6 - 1 bits are ever held
  rasterHeld_ += 6;
  const int bits = pixelBits();
  while (rasterHeld_ >= bits && rasterPixels_ > 0) {
    rasterHeld_ -= bits;
    const int value = static_cast<int>(rasterBits_ >> rasterHeld_) & ((1 << bits) - 1);
    writeAtBeam(value, 1);
    --rasterPixels_;
  }
  if (rasterPixels_ == 0) rasterHeld_ = 0;  // padding bits of the last character
  rasterBits_ &= (1u << rasterHeld_) - 1u;
}

// The beam moves right and wraps at the viewport's right edge to the next
// row up: the RAL GKS driver's GK4TRO sends a whole raster after one RS,
// bottom row first, so its pictures stand upright only so (raster-rows=down
// is the other reading). Work is bounded by the viewport: once the beam has
// left it across the top or bottom, nothing more can be drawn.
void Tek4125Decoder::writeAtBeam(int index, long count) {
  const int step = readings_.rasterRowsDown ? -1 : 1;
  while (count > 0 && (readings_.rasterRowsDown ? beamY_ >= vy0_ : beamY_ <= vy1_)) {
    if (beamX_ > vx1_) {
      beamX_ = vx0_;
      beamY_ += step;
      continue;
    }
    const long n = std::min<long>(count, vx1_ - beamX_ + 1);
    if (beamY_ >= vy0_ && beamY_ <= vy1_)
      for (long i = 0; i < n; ++i)
        if (beamX_ + i >= vx0_) plot(beamX_ + static_cast<int>(i), beamY_, index);
    beamX_ += static_cast<int>(n);
    count -= n;
  }
}

// Bits a pixel: as the last RU set (RAL GKS driver, GK4TRO, where they
// always equal its surface's planes), or surface 1's planes.
int Tek4125Decoder::pixelBits() const {
  return readings_.pixelBitsFromSurface ? std::bit_width(static_cast<unsigned>(mask_)) : bitsPerPixel_;
}

// ints_: count, run codes. A run code is length * 2^bits + index (RAL GKS
// driver, GK4TRO).
void Tek4125Decoder::runLengthWrite() {
  const int bits = pixelBits();
  for (std::size_t i = 1; i < ints_.size(); ++i) {
    const int code = ints_[i];
    if (code < 0) {
      malformed();
      continue;
    }
    writeAtBeam(code & ((1 << bits) - 1), code >> bits);
  }
}

void Tek4125Decoder::setColor(int index, int c1, int c2, int c3) {
  if (index < 0 || index >= profile_.colorMapSize()) return malformed();
  Rgb8 rgb;
  if (colorMode_ == 3) rgb = devices::tekHlsToRgb({c1, c2, c3});  // the 4027's and sixel's HLS too
  else if (colorMode_ == 2)  // CMY
    rgb = Rgb8{devices::eightOfPercent(100 - c1), devices::eightOfPercent(100 - c2), devices::eightOfPercent(100 - c3)};
  else
    rgb = Rgb8{devices::eightOfPercent(c1), devices::eightOfPercent(c2), devices::eightOfPercent(c3)};
  screen_.colormap[static_cast<std::size_t>(index)] = rgb;
}

void Tek4125Decoder::execute() {
  state_ = State::Ground;
  ++report_.commands;
  auto xy = [&](std::size_t i) { return i * 2 + 1 < xys_.size() ? xys_[i * 2] : 0; };
  auto xyY = [&](std::size_t i) { return i * 2 + 1 < xys_.size() ? xys_[i * 2 + 1] : 0; };
  auto intAt = [&](std::size_t i, int fallback) { return i < ints_.size() ? ints_[i] : fallback; };
  switch (spec_->action) {
    case Action::TM:
      if (const int mode = intAt(0, colorMode_); mode >= 1 && mode <= 3) colorMode_ = mode;
      else malformed();
      break;
    case Action::TG: {
      // ints_: surface, count, entries...
      const std::size_t entries = ints_.size() >= 2 ? ints_.size() - 2 : 0;
      if (entries % 4 != 0) malformed();
      for (std::size_t i = 0; i + 4 <= entries; i += 4)
        setColor(ints_[2 + i], ints_[3 + i], ints_[4 + i], ints_[5 + i]);
      break;
    }
    case Action::TB:  // taken as colour map entry 0, the colour the screen is cleared to (RAL-CGM TEKclose)
      setColor(0, intAt(0, 0), intAt(1, 0), intAt(2, 0));
      break;
    case Action::RD:  // ints_: count, planes of surface 1, ...; surface 1 keeps only its planes
      if (ints_.size() >= 2 && ints_[1] >= 1) mask_ = (1 << std::min(ints_[1], profile_.planes)) - 1;
      else malformed();
      break;
    case Action::KI: ignoreDel_ = intAt(0, 0) != 0; break;
    case Action::RL: runLengthWrite(); break;
    case Action::RU:
      alu_ = intAt(1, 11);
      if (const int bits = intAt(2, bitsPerPixel_); bits >= 1 && bits <= 8) bitsPerPixel_ = bits;
      else malformed();
      break;
    case Action::RS:
      vx0_ = std::clamp(std::min(xy(0), xy(1)), 0, profile_.width - 1);
      vx1_ = std::clamp(std::max(xy(0), xy(1)), 0, profile_.width - 1);
      vy0_ = std::clamp(std::min(xyY(0), xyY(1)), 0, profile_.height - 1);
      vy1_ = std::clamp(std::max(xyY(0), xyY(1)), 0, profile_.height - 1);
      beamX_ = vx0_;
      beamY_ = readings_.rasterRowsDown ? vy1_ : vy0_;  // the corner the first row starts at
      break;
    case Action::RH:  // relative to the viewport (zebra dev_4107.c), or as the profile reads it
      beamX_ = (readings_.rhFromScreen ? 0 : vx0_) + xy(0);
      beamY_ = (readings_.rhFromScreen ? 0 : vy0_) + xyY(0);
      break;
    case Action::RP:
      if (rasterPixels_ > 0) malformed();  // fewer characters than pixels
      rasterPixels_ = 0;
      break;
    case Action::RR: {  // screen pixels (PGPLOT tkdriv.f), or relative to the viewport as the profile reads it
      const int ox = readings_.rrFromViewport ? vx0_ : 0, oy = readings_.rrFromViewport ? vy0_ : 0;
      const int x0 = std::max(std::min(xy(0), xy(1)) + ox, 0);
      const int x1 = std::min(std::max(xy(0), xy(1)) + ox, profile_.width - 1);
      const int y0 = std::max(std::min(xyY(0), xyY(1)) + oy, 0);
      const int y1 = std::min(std::max(xyY(0), xyY(1)) + oy, profile_.height - 1);
      if (x0 > x1 || y0 > y1) break;
      // Row by row, as plot() would set each pixel (mask, then XOR or copy):
      // a fill costs what copying its rows costs.
      const std::size_t width = static_cast<std::size_t>(x1 - x0 + 1);
      if (!chargePixelWork(report_, width * static_cast<std::size_t>(y1 - y0 + 1))) break;
      const auto value = static_cast<PaletteIndex>(intAt(0, 0) & mask_);
      for (int y = y0; y <= y1; ++y) {
        PaletteIndex* row = devices::pixelAt(screen_, x0, y);
        if (alu_ == 7)
          for (std::size_t i = 0; i < width; ++i) row[i] = static_cast<PaletteIndex>(row[i] ^ value);
        else
          std::fill_n(row, width, value);
      }
      break;
    }
    case Action::LF:
      penX_ = xy(0);
      penY_ = xyY(0);
      break;
    case Action::LG:
      if (panelOpen_) {
        if (panel_.size() / 2 < kMaxPanelPoints) panel_.insert(panel_.end(), {xy(0), xyY(0)});
        else malformed();
      } else {
        line(penX_, penY_, xy(0), xyY(0), lineIndex_);
      }
      penX_ = xy(0);
      penY_ = xyY(0);
      break;
    case Action::ML: lineIndex_ = intAt(0, lineIndex_); break;
    case Action::MP: fillPattern_ = intAt(0, fillPattern_); break;
    case Action::LP:
      if (panelOpen_) fillPanel();  // a new panel ends the open one
      panelOpen_ = true;
      panelBoundary_ = intAt(0, 0) != 0;
      panel_.assign({xy(0), xyY(0)});
      penX_ = xy(0);
      penY_ = xyY(0);
      break;
    case Action::LE:
      if (panelOpen_) fillPanel();
      else malformed();
      break;
    case Action::Accept: break;
  }
}

std::unique_ptr<Tek4125Decoder> makeTek4125Decoder(const Tek4125Profile& profile) {
  return std::make_unique<Tek4125Decoder>(profile);
}

}  // namespace lattice::tek4125
