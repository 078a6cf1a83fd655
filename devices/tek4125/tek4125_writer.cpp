#include "devices/tek4125/tek4125_writer.hpp"

#include <algorithm>

namespace lattice::tek4125 {

namespace {
constexpr std::uint8_t kDel = 0x7F;
}

void Tek4125Writer::countDels(std::size_t from) {
  if (forms_.escapeDel)
    dels_ += static_cast<std::size_t>(std::count(out_.begin() + static_cast<long>(from), out_.end(), kDel));
}

void Tek4125Writer::integer(int value) {
  const std::size_t before = out_.size();
  tek4125::appendInt(out_, value);
  countDels(before);
  spillIfFull();
}

void Tek4125Writer::xy(int x, int y) {
  const std::size_t before = out_.size();
  if (highShortNow()) {
    xy_.appendHighShort(out_, x, y);
  } else {
    if (forms_.fullXy) xy_.reset();  // no register is relied on: all five bytes
    xy_.append(out_, x, y);
  }
  lastXyInPixelCommand_ = pixelCommand_;
  countDels(before);
  spillIfFull();
}

void Tek4125Writer::spill() {
  if (out_.empty()) return;
  const tek4125::Bytes* ready = &out_;
  if (forms_.escapeDel && dels_ > 0) {
    // Command names are capitals and raster characters stay below 0x60, so
    // every DEL here is inside an integer or a coordinate.
    escaped_.clear();
    for (std::uint8_t c : out_) {
      if (c == kDel) escaped_.insert(escaped_.end(), {tek4125::kEsc, '?'});
      else escaped_.push_back(c);
    }
    ready = &escaped_;
  }
  sink_.write(std::span<const std::uint8_t>(*ready));
  spilled_ += ready->size();
  out_.clear();
  dels_ = 0;
}

}  // namespace lattice::tek4125
