#include "devices/sixel/sixel_driver.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "devices/gun_percent.hpp"
#include "devices/sixel/sixel_forms.hpp"
#include "foundation/error.hpp"

namespace lattice::sixel {

std::string sixelHeader(const SixelProfile& p, const FrameInfo& frame) {
  std::string out(kDcs);
  // Trailing default (zero) parameters are left out: "ESC P q" is P1 = P2 = P3 = 0.
  if (p.p2 != 0) out += fmt::format("{};{}", p.p1, p.p2);
  else if (p.p1 != 0) out += fmt::format("{}", p.p1);
  out += kSixelFinal;
  out += fmt::format("{}1;1;{};{}", kRaster, frame.width, frame.height);
  for (std::size_t i = 0; i < frame.palette.size(); ++i) {
    const Rgb8 c = frame.palette[i];
    out += fmt::format("{}{};{};{};{};{}", kColour, i, kColourSpaceRgb, devices::percentOf8(c.r), devices::percentOf8(c.g),
                       devices::percentOf8(c.b));
  }
  return out;
}

SixelDriver::SixelDriver(ByteSink& sink, SixelProfile profile) : sink_(sink), profile_(profile) {
  profile_.validate();
}

void SixelDriver::begin(const FrameInfo& frame) {
  if (frame.width < 1 || frame.height < 1 || frame.width > profile_.width || frame.height > profile_.height)
    throw Error(ErrorKind::Usage,
                fmt::format("sixel: a {}x{} picture does not fit the terminal's {}x{} (--set width=... height=...; "
                            "xterm's maxGraphicSize resource sets its limit)",
                            frame.width, frame.height, profile_.width, profile_.height));
  if (frame.palette.empty() || frame.palette.size() > static_cast<std::size_t>(profile_.registers))
    throw Error(ErrorKind::Usage, fmt::format("sixel: {} colours, but the terminal has {} registers (--set "
                                              "registers=256 for xterm with numColorRegisters: 256)",
                                              frame.palette.size(), profile_.registers));
  frame_ = frame;
  band_.assign(static_cast<std::size_t>(frame.width) * kBandRows, 0);
  bandRows_ = 0;
  nextRow_ = 0;
  encoder_ = std::make_unique<SixelBandEncoder>(frame.width, static_cast<int>(frame.palette.size()));
  stats_ = {};
  stats_.registers = frame.palette.size();
  put(sixelHeader(profile_, frame));
}

void SixelDriver::row(int y, std::span<const PaletteIndex> indices) {
  if (nextRow_ < 0 || y != nextRow_ || indices.size() != static_cast<std::size_t>(frame_.width))
    throw Error(ErrorKind::Internal, fmt::format("sixel: row {} out of order or of the wrong width", y));
  const std::size_t limit = frame_.palette.size();
  PaletteIndex* dst = band_.data() + static_cast<std::size_t>(bandRows_) * indices.size();
  for (std::size_t x = 0; x < indices.size(); ++x) {
    if (indices[x] >= limit)
      throw Error(ErrorKind::Internal, fmt::format("sixel: index {} beyond the palette of {}", indices[x], limit));
    dst[x] = indices[x];
  }
  ++nextRow_;
  if (++bandRows_ == kBandRows) flushBand();
}

void SixelDriver::flushBand() {
  if (bandRows_ == 0) return;
  out_.clear();
  if (stats_.bands > 0) out_ += kNewLine;
  encoder_->encode(band_, bandRows_, out_);
  put(out_);
  ++stats_.bands;
  bandRows_ = 0;
}

void SixelDriver::end() {
  if (nextRow_ != frame_.height) throw Error(ErrorKind::Internal, "sixel: end() before every row arrived");
  flushBand();
  put(std::string(kSt));
  stats_.band = encoder_->stats();
  sink_.flush();
}

void SixelDriver::put(const std::string& bytes) {
  sink_.write(bytes);
  stats_.bytes += bytes.size();
}

}  // namespace lattice::sixel
