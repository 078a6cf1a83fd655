#include "devices/tek4014/tek4014_driver.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice::tek4014 {

Tek4014Driver::Tek4014Driver(ByteSink& sink, Tek4014Profile profile)
    : sink_(sink), profile_(profile), encoder_(profile.addressBits == 12) {}

void Tek4014Driver::write(const std::string& bytes) {
  sink_.write(std::string_view(bytes));
  stats_.bytes += bytes.size();
}

void Tek4014Driver::begin(const FrameInfo& frame) {
  if (frame.width < 1 || frame.height < 1 || frame.width > profile_.width() || frame.height > profile_.height())
    throw Error(ErrorKind::Usage,
                fmt::format("tek4014: a {}x{} frame does not fit the {}-bit screen's {}x{} addresses; render with a "
                            "size of at most {}x{}{}",
                            frame.width, frame.height, profile_.addressBits, profile_.width(), profile_.height(),
                            profile_.width(), profile_.height(),
                            profile_.addressBits == 10 ? " (or --set bits=12 for 4096x3120)" : ""));
  if (frame.palette.empty() || frame.palette.size() > 256)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4014: the palette has {} colours; it needs 1 to 256", frame.palette.size()));
  frame_ = frame;
  dither_.clear();
  dither_.emplace_back(profile_.dither, frame.width, frame.palette);
  lit_.assign(static_cast<std::size_t>(frame.width), 0);
  encoder_ = AddressEncoder(profile_.addressBits == 12);
  stats_ = {};
  mode_ = Mode::Alpha;
  write(std::string{kEsc, kFormFeed});
  nextRow_ = 0;
}

void Tek4014Driver::row(int y, std::span<const PaletteIndex> indices) {
  if (nextRow_ < 0 || y != nextRow_ || static_cast<int>(indices.size()) != frame_.width)
    throw Error(ErrorKind::Internal,
                fmt::format("tek4014: row {} of width {} arrived out of order (expected row {} of width {})", y,
                            indices.size(), nextRow_, frame_.width));
  for (PaletteIndex i : indices)
    if (i >= frame_.palette.size())
      throw Error(ErrorKind::Internal, fmt::format("tek4014: row {} uses palette index {} but the palette has {} "
                                                   "entries",
                                                   y, int(i), frame_.palette.size()));
  dither_.front().row(y, indices, lit_);
  ++nextRow_;

  const int shift = profile_.shift();
  const int ty = (frame_.height - 1 - y) << shift;
  const int w = frame_.width;
  // Both forms from the same starting state; the shorter one is sent.
  AddressEncoder asPoints = encoder_, asVectors = encoder_;
  points_.clear();
  vectors_.clear();
  if (mode_ != Mode::Points) points_.push_back(kPointPlot);
  std::uint64_t dots = 0, runs = 0;
  for (int x = 0; x < w;) {
    if (!lit_[static_cast<std::size_t>(x)]) {
      ++x;
      continue;
    }
    int last = x;
    while (last + 1 < w && lit_[static_cast<std::size_t>(last + 1)]) ++last;
    for (int d = x; d <= last; ++d) asPoints.encode(d << shift, ty, points_);
    vectors_.push_back(kGraph);
    asVectors.encode(x << shift, ty, vectors_);
    asVectors.encode(last << shift, ty, vectors_);
    dots += static_cast<std::uint64_t>(last - x + 1);
    ++runs;
    x = last + 1;
  }
  if (runs == 0) return;
  stats_.dots += dots;
  if (points_.size() <= vectors_.size()) {
    write(points_);
    encoder_ = asPoints;
    mode_ = Mode::Points;
    ++stats_.pointRows;
  } else {
    write(vectors_);
    encoder_ = asVectors;
    mode_ = Mode::Vectors;
    ++stats_.vectorRows;
    stats_.vectors += runs;
  }
}

void Tek4014Driver::end() {
  if (nextRow_ != frame_.height)
    throw Error(ErrorKind::Internal,
                fmt::format("tek4014: end() after {} of {} rows", nextRow_ < 0 ? 0 : nextRow_, frame_.height));
  std::string tail{kGraph};
  encoder_.encode(0, kHomeY, tail);
  tail.push_back(kAlpha);
  write(tail);
  sink_.flush();
  nextRow_ = -1;
}

}  // namespace lattice::tek4014
