#include "devices/sixel/sixel_decoder.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "devices/gun_percent.hpp"
#include "devices/sixel/sixel_forms.hpp"
#include "devices/tek_hls.hpp"
#include "devices/work_budget.hpp"

namespace lattice::sixel {
namespace {

bool isDigit(std::uint8_t b) { return b >= '0' && b <= '9'; }
bool isSixel(std::uint8_t b) { return b >= kSixelFirst && b <= kSixelLast; }

}  // namespace

SixelDecoder::SixelDecoder(SixelProfile profile) : profile_(profile) {
  profile_.validate();
  registers_.assign(static_cast<std::size_t>(profile_.registers), Rgb8{});
  register_ = 3 % profile_.registers;  // xterm's starting register
}

void SixelDecoder::feed(std::span<const std::uint8_t> bytes) {
  report_.bytes += bytes.size();
  for (std::uint8_t b : bytes) consume(b);
}

void SixelDecoder::finish() {
  if (state_ == State::Sixel || state_ == State::SixelEscape) {
    if (pending_ != 0) finishPending(0);
    ++report_.malformed;  // a sixel string the end cut off: what it drew stays
  } else if (state_ == State::DcsParams || state_ == State::Ignore || state_ == State::IgnoreEscape ||
             state_ == State::Csi || state_ == State::Escape) {
    ++report_.malformed;
  }
  state_ = State::Ground;
  pending_ = 0;
}

void SixelDecoder::consume(std::uint8_t b) {
  switch (state_) {
    case State::Ground: ground(b); break;
    case State::Escape: escape(b); break;
    case State::Csi:
      if (b >= 0x40 && b <= 0x7E) {
        unknown(fmt::format("CSI {}", static_cast<char>(b)));
        state_ = State::Ground;
      } else if (b == kEsc) {
        ++report_.malformed;
        state_ = State::Escape;
      }
      break;
    case State::DcsParams: dcsParams(b); break;
    case State::Sixel: sixel(b); break;
    case State::SixelEscape:
      if (b == '\\') {
        endImage();
      } else {  // ESC inside the string ends it badly; the ESC starts something new
        ++report_.malformed;
        state_ = State::Escape;
        escape(b);
      }
      break;
    case State::Ignore:
      if (b == kEsc) state_ = State::IgnoreEscape;
      else if (b == kSt8) state_ = State::Ground;
      break;
    case State::IgnoreEscape:
      state_ = b == '\\' ? State::Ground : State::Ignore;
      break;
  }
}

void SixelDecoder::ground(std::uint8_t b) {
  if (b == kEsc) {
    inStrayText_ = false;
    state_ = State::Escape;
  } else if (b == kDcs8) {
    inStrayText_ = false;
    params_.clear();
    state_ = State::DcsParams;
  } else if (b == '\r' || b == '\n' || b == ' ' || b == '\t' || b == 0) {
    // Spacing between strings: nothing to show.
  } else {
    stray();
  }
}

void SixelDecoder::escape(std::uint8_t b) {
  if (b == 'P') {
    params_.clear();
    state_ = State::DcsParams;
  } else if (b == '[') {
    state_ = State::Csi;
  } else if (b == '\\') {
    state_ = State::Ground;  // a stray ST ends nothing
  } else if (b == kEsc) {
    ++report_.malformed;
  } else {
    unknown(fmt::format("ESC {:#04x}", b));
    state_ = State::Ground;
  }
}

void SixelDecoder::dcsParams(std::uint8_t b) {
  if (params_.empty()) params_.push_back(0);
  if (isDigit(b)) {
    params_.back() = std::min<std::uint32_t>(kMaxNumber, params_.back() * 10 + (b - '0'));
  } else if (b == ';') {
    if (params_.size() < kMaxParams) params_.push_back(0);
  } else if (b == static_cast<std::uint8_t>(kSixelFinal)) {
    startImage();
  } else if (b >= 0x40 && b <= 0x7E) {
    unknown(fmt::format("DCS {}", static_cast<char>(b)));
    state_ = State::Ignore;
  } else if (b == kEsc) {
    ++report_.malformed;
    state_ = State::Escape;
  } else if (b >= 0x20 && b <= 0x2F) {
    // An intermediate byte: part of some other DCS; its final decides.
  } else {
    ++report_.malformed;
    state_ = State::Ignore;
  }
}

void SixelDecoder::startImage() {
  ++report_.commands;
  ++images_;
  background_ = params_.size() > 1 ? static_cast<int>(params_[1]) : 0;
  filled_ = false;
  declaredWidth_ = declaredHeight_ = 0;
  col_ = row_ = 0;
  pending_ = 0;
  params_.clear();
  state_ = State::Sixel;
}

void SixelDecoder::endImage() {
  if (pending_ != 0) finishPending(0);
  ++report_.commands;
  state_ = State::Ground;
}

void SixelDecoder::sixel(std::uint8_t b) {
  if (pending_ != 0) {
    if (isDigit(b)) {
      params_.back() = std::min<std::uint32_t>(kMaxNumber, params_.back() * 10 + (b - '0'));
      return;
    }
    if (b == ';') {
      if (params_.size() < kMaxParams) params_.push_back(0);
      return;
    }
    if (finishPending(b)) return;
  }
  if (isSixel(b)) {
    draw(static_cast<std::uint8_t>(b - kSixelFirst), 1);
  } else if (b == kColour || b == kRaster || b == kRepeat) {
    pending_ = static_cast<char>(b);
    params_.assign(1, 0);
  } else if (b == kCarriageReturn) {
    ++report_.commands;
    col_ = 0;
  } else if (b == kNewLine) {
    ++report_.commands;
    col_ = 0;
    row_ = std::min(row_ + kBandRows, profile_.height + kBandRows);  // past the canvas nothing draws
  } else if (b == kEsc) {
    state_ = State::SixelEscape;
  } else if (b == kSt8) {
    endImage();
  } else if (b == 0x18 || b == 0x1A) {  // CAN, SUB: the string is cancelled
    ++report_.malformed;
    pending_ = 0;
    state_ = State::Ground;
  } else if (b < 0x20 || b == 0x7F) {
    // Controls inside the string are ignored (xterm skips CR, LF and space too).
  } else if (b != ' ') {
    ++report_.malformed;
  }
}

bool SixelDecoder::finishPending(std::uint8_t next) {
  const char command = pending_;
  pending_ = 0;
  if (command == kColour) {
    defineOrSelect();
    return false;
  }
  if (command == kRaster) {
    raster();
    return false;
  }
  // A repeat: its sixel is the byte after the count.
  if (!isSixel(next)) {
    ++report_.malformed;
    return false;
  }
  ++report_.commands;
  draw(static_cast<std::uint8_t>(next - kSixelFirst), params_[0]);
  return true;
}

void SixelDecoder::defineOrSelect() {
  const int reg = static_cast<int>(params_[0] % static_cast<std::uint32_t>(profile_.registers));
  if (params_.size() == 1) {
    ++report_.commands;
    register_ = reg;
    return;
  }
  if (params_.size() != 5) {
    ++report_.malformed;
    return;
  }
  const std::uint32_t space = params_[1], x = params_[2], y = params_[3], z = params_[4];
  if (space == kColourSpaceRgb && x <= 100 && y <= 100 && z <= 100) {
    registers_[static_cast<std::size_t>(reg)] = {devices::eightOfPercent(static_cast<int>(x)), devices::eightOfPercent(static_cast<int>(y)),
                                                 devices::eightOfPercent(static_cast<int>(z))};
  } else if (space == kColourSpaceHls && x <= 360 && y <= 100 && z <= 100) {
    registers_[static_cast<std::size_t>(reg)] =
        devices::tekHlsToRgb({static_cast<int>(x), static_cast<int>(y), static_cast<int>(z)});
  } else {
    ++report_.malformed;
    return;
  }
  ++report_.commands;
  dirty_ = true;
}

void SixelDecoder::raster() {
  if (params_.size() < 2 || params_[0] == 0 || params_[1] == 0) {
    ++report_.malformed;
    return;
  }
  ++report_.commands;
  if (params_.size() < 4) return;
  if (params_[2] == 0 || params_[3] == 0 || params_[2] > static_cast<std::uint32_t>(profile_.width) ||
      params_[3] > static_cast<std::uint32_t>(profile_.height))
    ++report_.malformed;  // declared beyond the terminal: clipped to it
  declaredWidth_ = static_cast<int>(std::min<std::uint32_t>(params_[2], static_cast<std::uint32_t>(profile_.width)));
  declaredHeight_ =
      static_cast<int>(std::min<std::uint32_t>(params_[3], static_cast<std::uint32_t>(profile_.height)));
  extentWidth_ = std::max(extentWidth_, declaredWidth_);
  extentHeight_ = std::max(extentHeight_, declaredHeight_);
  dirty_ = true;
}

void SixelDecoder::ensureRows(int rows) {
  if (rows <= rows_) return;
  rows_ = rows;
  pixels_.resize(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(profile_.width), 0);
}

void SixelDecoder::fillBackground() {
  filled_ = true;
  if (background_ == 1 || declaredWidth_ == 0 || declaredHeight_ == 0) return;
  const auto w = static_cast<std::uint64_t>(declaredWidth_), h = static_cast<std::uint64_t>(declaredHeight_);
  if (!chargePixelWork(report_, w * h)) return;
  ensureRows(declaredHeight_);
  for (int y = 0; y < declaredHeight_; ++y)
    std::fill_n(pixels_.begin() + static_cast<std::ptrdiff_t>(y) * profile_.width, declaredWidth_, 0);
}

void SixelDecoder::draw(std::uint8_t bits, std::uint32_t count) {
  if (!filled_) fillBackground();
  const int start = col_;
  col_ = static_cast<int>(std::min<std::uint64_t>(std::uint64_t(col_) + count, std::uint64_t(profile_.width)));
  if (bits == 0 || start >= profile_.width || row_ >= profile_.height) return;
  const int visible = col_ - start;
  if (!chargePixelWork(report_, std::uint64_t(visible) * kBandRows)) return;
  const int lastRow = std::min(row_ + kBandRows, profile_.height);
  int bottom = row_;
  for (int r = row_; r < lastRow; ++r)
    if (bits & (1u << (r - row_))) bottom = r + 1;
  ensureRows(bottom);
  const auto reg = static_cast<PaletteIndex>(register_);
  for (int r = row_; r < bottom; ++r) {
    if (!(bits & (1u << (r - row_)))) continue;
    std::fill_n(pixels_.begin() + static_cast<std::ptrdiff_t>(r) * profile_.width + start, visible, reg);
  }
  extentWidth_ = std::max(extentWidth_, col_);
  extentHeight_ = std::max(extentHeight_, bottom);
  dirty_ = true;
}

const IndexedImage& SixelDecoder::image() const {
  if (!dirty_) return view_;
  const int w = std::max(1, extentWidth_), h = std::max(1, extentHeight_);
  view_ = IndexedImage(w, h, registers_.size());
  view_.colormap = registers_;
  for (int y = 0; y < std::min(h, rows_); ++y)
    std::copy_n(pixels_.begin() + static_cast<std::ptrdiff_t>(y) * profile_.width, w,
                view_.pixels.begin() + static_cast<std::ptrdiff_t>(y) * w);
  dirty_ = false;
  return view_;
}

void SixelDecoder::unknown(const std::string& name) {
  ++report_.unknownCommands;
  if (report_.unknownByName.size() < kMaxUnknownNames || report_.unknownByName.count(name) != 0)
    ++report_.unknownByName[name];
  else
    ++report_.unknownByName["(other)"];
}

void SixelDecoder::stray() {
  if (!inStrayText_) ++report_.malformed;  // once per run of text
  inStrayText_ = true;
}

}  // namespace lattice::sixel
