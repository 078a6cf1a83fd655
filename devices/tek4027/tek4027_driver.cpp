#include "devices/tek4027/tek4027_driver.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "foundation/error.hpp"

namespace lattice::tek4027 {

Tek4027Driver::Tek4027Driver(ByteSink& sink, Tek4027Profile profile, Tek4027Strategy strategy,
                             Tek4027Orientation orientation)
    : sink_(sink), profile_(profile), strategy_(strategy), orientation_(orientation) {
  profile_.validate();
  potOf_.fill(-1);
}

void Tek4027Driver::begin(const FrameInfo& frame) {
  if (frame.width < 1 || frame.height < 1 || frame.width > profile_.width || frame.height > profile_.height)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4027: a {}x{} frame does not fit the terminal's {}x{} graphics area; render "
                            "with a size of at most {}x{} (or change the tek4027 profile's resolution)",
                            frame.width, frame.height, profile_.width, profile_.height, profile_.width,
                            profile_.height));
  if (frame.palette.empty() || static_cast<int>(frame.palette.size()) > profile_.colors)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4027: the palette has {} colours but the terminal has {} paint pots; quantize "
                            "to at most {} colours",
                            frame.palette.size(), profile_.colors, profile_.colors));
  frame_ = frame;
  pixels_.assign(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0);
  nextRow_ = 0;
}

void Tek4027Driver::row(int y, std::span<const PaletteIndex> indices) {
  if (nextRow_ < 0 || y != nextRow_ || y >= frame_.height || static_cast<int>(indices.size()) != frame_.width)
    throw Error(ErrorKind::Internal,
                fmt::format("tek4027: row {} of width {} arrived out of order (expected row {} of width {})", y,
                            indices.size(), nextRow_, frame_.width));
  for (PaletteIndex i : indices)
    if (i >= frame_.palette.size())
      throw Error(ErrorKind::Internal,
                  fmt::format("tek4027: row {} uses palette index {} but the palette has {} entries", y, int(i),
                              frame_.palette.size()));
  std::copy(indices.begin(), indices.end(),
            pixels_.begin() + static_cast<std::ptrdiff_t>(y) * static_cast<std::ptrdiff_t>(frame_.width));
  ++nextRow_;
}

void Tek4027Driver::end() {
  if (nextRow_ != frame_.height)
    throw Error(ErrorKind::Internal,
                fmt::format("tek4027: end() after {} of {} rows", std::max(nextRow_, 0), frame_.height));

  // The most frequent index is erased to rather than drawn: it costs nothing.
  std::array<std::uint64_t, 256> count{};
  for (PaletteIndex i : pixels_) ++count[i];
  const std::size_t paletteSize = frame_.palette.size();
  std::size_t background = 0;
  for (std::size_t i = 1; i < paletteSize; ++i)
    if (count[i] > count[background]) background = i;

  potOf_.fill(-1);
  potOf_[background] = profile_.backgroundPot;
  int pot = 0;
  for (std::size_t i = 0; i < paletteSize; ++i) {
    if (i == background) continue;
    if (pot == profile_.backgroundPot) ++pot;
    potOf_[i] = pot++;
  }

  Tek4027Picture picture;
  picture.frame.width = frame_.width;
  picture.frame.height = frame_.height;
  picture.frame.backgroundPot = profile_.backgroundPot;
  picture.frame.pots.resize(pixels_.size());
  std::transform(pixels_.begin(), pixels_.end(), picture.frame.pots.begin(),
                 [&](PaletteIndex i) { return static_cast<std::uint8_t>(potOf_[i]); });
  // Define only the pots that appear (and always the background, for the erase).
  for (std::size_t i = 0; i < paletteSize; ++i)
    if (count[i] > 0 || i == background)
      picture.potColours[static_cast<std::size_t>(potOf_[i])] = frame_.palette[i];

  const std::string text = encodeTek4027(picture, profile_, strategy_, &stats_, orientation_);
  // In pieces, so a slow sink (a serial line with flow control) can report
  // progress and pace itself as the picture goes out; with report pacing and
  // a terminal to answer, one record at a time.
  constexpr std::size_t kPiece = 1024;
  std::size_t at = 0;
  auto writeUpTo = [&](std::size_t end) {
    for (; at < end; at += std::min(kPiece, end - at))
      sink_.write(std::string_view(text).substr(at, std::min(kPiece, end - at)));
  };
  for (std::size_t end : reportRecordEnds(text, profile_)) {
    writeUpTo(end);
    if (replies_ != nullptr) {
      sink_.flush();
      replies_->awaitReply();
    }
  }
  writeUpTo(text.size());
  sink_.flush();
  nextRow_ = -1;
}

}  // namespace lattice::tek4027
