#include "devices/tek4014/tek4014_decoder.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "devices/tek4014/tek4014_driver.hpp"
#include "devices/work_budget.hpp"

namespace lattice::tek4014 {
namespace {

constexpr std::uint8_t kBel = 0x07, kBs = 0x08, kHt = 0x09, kLf = 0x0A, kVt = 0x0B, kCr = 0x0D;

// ESC and a byte: what xterm's Tesctable makes of it.
enum class EscAction { Leave, Stay, Control, Page, Size, Beam, Osc, Known };

EscAction escAction(std::uint8_t b) {
  // Ignored, still escaped (xterm's Tesctable: LF, CR, ESC, '~' and the high half).
  if (b == kLf || b == kCr || b == 0x1B || b == 0x7E || b >= 0x80) return EscAction::Stay;
  if (b == kBel || b == kBs || b == kHt || b == kVt || (b >= 0x1C && b <= 0x1F)) return EscAction::Control;
  if (b == 0x0C) return EscAction::Page;
  if (b == 0x03 || b == 0x05 || b == 0x0E || b == 0x0F || b == 0x17 || b == 0x18 || b == 0x1A) return EscAction::Known;
  if (b >= 0x38 && b <= 0x3B) return EscAction::Size;
  if (b == 0x5D) return EscAction::Osc;
  if ((b >= 0x60 && b <= 0x64) || (b >= 0x67 && b <= 0x6C) || (b >= 0x6F && b <= 0x74) || b == 0x77)
    return EscAction::Beam;
  return EscAction::Leave;
}

}  // namespace

Tek4014Decoder::Tek4014Decoder(Tek4014Profile profile)
    : profile_(profile), screen_(profile.width(), profile.height()) {
  beamY_ = kHomeY;
}

const IndexedImage& Tek4014Decoder::image() const {
  if (stale_) {
    if (picture_.pixels.empty()) {
      picture_ = IndexedImage(screen_.width(), screen_.height(), 2);
      picture_.colormap[0] = {0, 0, 0};        // dark
      picture_.colormap[1] = {255, 255, 255};  // lit
    }
    screen_.paint(picture_);
    stale_ = false;
  }
  return picture_;
}

void Tek4014Decoder::feed(std::span<const std::uint8_t> bytes) {
  report_.bytes += bytes.size();
  for (std::uint8_t b : bytes) consume(b);
}

void Tek4014Decoder::finish() {
  if (address_.inProgress() || escape_ != Escape::None) ++report_.malformed;  // cut off by the end
  address_.start();
  escape_ = Escape::None;
  inText_ = false;
}

void Tek4014Decoder::unknown(const std::string& name) {
  ++report_.unknownCommands;
  ++report_.unknownByName[name];  // names are few and fixed (an ESC byte at most), so the map stays small
}

void Tek4014Decoder::consume(std::uint8_t b) {
  if (escape_ == Escape::Osc) {
    // Skipped to BEL; xterm stops at a non-printable byte or a full buffer too.
    if (b == kBel || (b & 0x7F) < 0x20 || (b & 0x7F) == 0x7F || ++oscBytes_ >= kMaxOsc) escape_ = Escape::None;
    return;
  }
  if (escape_ == Escape::Pending) {
    escaped(b);
    return;
  }
  const bool gs = afterGs_;
  afterGs_ = false;
  if (b < 0x20) {
    if (gs && b == kBel) {  // GS BEL: the first vector is drawn, not moved
      penDown_ = true;
      return;
    }
    control(b);
    return;
  }
  if (bypass_) return;  // after ESC CAN or GIN: everything but controls is ignored
  if (mode_ == Mode::Alpha) {
    if (b == 0x20 || (b >= 0x7F && b < 0xA0)) {
      inText_ = false;  // a space moves the cursor; these bytes are ignored
      return;
    }
    if (!inText_) unknown("alpha text (not drawn)");
    inText_ = true;
    return;
  }
  if (mode_ == Mode::Incremental) {
    incremental(b);
    return;
  }
  graphic(b);
}

void Tek4014Decoder::abandonAddress() {
  if (address_.inProgress()) ++report_.malformed;  // a control byte cut an address short
  address_.start();
  haveIntensity_ = false;
}

void Tek4014Decoder::enter(Mode mode) {
  mode_ = mode;
  bypass_ = false;
  inText_ = false;
  ++report_.commands;
}

void Tek4014Decoder::control(std::uint8_t b) {
  abandonAddress();
  inText_ = false;
  switch (b) {
    case 0x1B: escape_ = Escape::Pending; return;
    case 0x1C: enter(Mode::Point); return;
    case 0x1D:
      enter(Mode::Graph);
      penDown_ = false;
      afterGs_ = true;
      return;
    case 0x1E: enter(Mode::Incremental); return;
    case 0x1F: enter(Mode::Alpha); return;
    case kCr:
      beamX_ = 0;
      enter(Mode::Alpha);
      return;
    case kBel: case kBs: case kHt: case kVt:
      bypass_ = false;
      return;
    default: return;  // LF and the rest: no drawing (alpha cursor motions are not followed)
  }
}

void Tek4014Decoder::escaped(std::uint8_t b) {
  switch (escAction(b)) {
    case EscAction::Stay: return;
    case EscAction::Control:
      escape_ = Escape::None;
      if (b == 0x1C) {  // ESC FS: special point plot
        abandonAddress();
        enter(Mode::SpecialPoint);
      } else {
        control(b);
      }
      return;
    case EscAction::Page:
      escape_ = Escape::None;
      page();
      return;
    case EscAction::Size:
      escape_ = Escape::None;
      ++report_.commands;  // character size: no text is drawn here
      return;
    case EscAction::Beam: {
      escape_ = Escape::None;
      const int style = b & 7;
      if (style <= 4) lineStyle_ = style;
      ++report_.commands;
      return;
    }
    case EscAction::Osc:
      escape_ = Escape::Osc;
      oscBytes_ = 0;
      ++report_.commands;
      return;
    case EscAction::Known:
      escape_ = Escape::None;
      if (b == 0x18 || b == 0x1A) bypass_ = true;  // bypass, and GIN's bypass until the answer
      ++report_.commands;
      return;
    case EscAction::Leave:
      escape_ = Escape::None;
      unknown(fmt::format("ESC 0x{:02X}", b));
      return;
  }
}

void Tek4014Decoder::page() {
  // Erasing costs the screen: two bytes must not buy unbounded work.
  const auto pixels = static_cast<std::uint64_t>(screen_.width()) * static_cast<std::uint64_t>(screen_.height());
  if (chargePixelWork(report_, pixels)) {
    screen_.clear();
    stale_ = true;
  }
  abandonAddress();
  mode_ = Mode::Alpha;
  bypass_ = false;
  beamX_ = 0;
  beamY_ = kHomeY;
  ++report_.commands;
}

void Tek4014Decoder::graphic(std::uint8_t b) {
  if (!address_.inProgress()) {
    if (b >= 0x80) return;  // ignored where an address could start
    if (mode_ == Mode::SpecialPoint && !haveIntensity_) {
      haveIntensity_ = true;  // the dot's intensity: one brightness here
      return;
    }
  }
  if (!address_.add(b)) return;
  haveIntensity_ = false;
  ++report_.commands;
  if (mode_ == Mode::Graph) {
    moveOrDraw(address_.x(), address_.y(), penDown_);
    penDown_ = true;
  } else {
    moveOrDraw(address_.x(), address_.y(), false);
    moveOrDraw(address_.x(), address_.y(), true);
  }
}

void Tek4014Decoder::incremental(std::uint8_t b) {
  if (b == 0x20) {
    penDown_ = false;
    return;
  }
  if (b == 0x50) {
    penDown_ = true;
    return;
  }
  // Direction bits: 1 east, 2 west, 4 north, 8 south (A, B, D, E, F, H, I, J).
  if (b < 0x41 || b > 0x4A || b == 0x43 || b == 0x47) return;
  // Clamped far off the screen, so a stream of steps cannot overflow.
  constexpr int kFar = 1 << 16;
  int x = beamX_, y = beamY_;
  if (b & 4) y = std::min(y + 1, kFar);
  else if (b & 8) y = std::max(y - 1, -kFar);
  if (b & 1) x = std::min(x + 1, kFar);
  else if (b & 2) x = std::max(x - 1, -kFar);
  ++report_.commands;
  moveOrDraw(x, y, penDown_);
}

void Tek4014Decoder::moveOrDraw(int x, int y, bool draw) {
  if (draw) {
    const int s = profile_.shift();
    const Tek4014Screen::Vector v = screen_.vector(beamX_ >> s, beamY_ >> s, x >> s, y >> s);
    if (lineStyle_ != 0) ++report_.unknownByName["dashed line style (drawn solid)"];
    if (chargePixelWork(report_, v.work()) && v.last >= v.first) {
      screen_.draw(v);
      stale_ = true;
    }
  }
  beamX_ = x;
  beamY_ = y;
}

}  // namespace lattice::tek4014
