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
  const std::span<const std::uint8_t> all(out_);
  if (forms_.escapeDel && dels_ > 0) {
    // Command names are capitals and raster characters stay below 0x60, so
    // every DEL here is inside an integer or a coordinate. The pieces
    // between DELs go to the sink as they are, each DEL as ESC ?: no second
    // buffer.
    static constexpr std::uint8_t kEscapedDel[] = {tek4125::kEsc, '?'};
    std::size_t start = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (all[i] != kDel) continue;
      if (i > start) sink_.write(all.subspan(start, i - start));
      sink_.write(std::span<const std::uint8_t>(kEscapedDel));
      start = i + 1;
    }
    if (start < all.size()) sink_.write(all.subspan(start));
    spilled_ += all.size() + dels_;
  } else {
    sink_.write(all);
    spilled_ += all.size();
  }
  out_.clear();
  dels_ = 0;
}

}  // namespace lattice::tek4125
