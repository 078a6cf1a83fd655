#pragma once
// The 4027 driver: an IndexedSink of at most 8 colours writing the terminal's
// command language to a ByteSink. The whole frame is kept (at most the
// profile's area, 640x350 bytes in strict) because the stream starts with the
// erase colour, the most frequent colour of the frame, and because drawing
// one pot at a time needs every row before the first vector.
//
// Palette indices are renumbered to paint pots: the most frequent index
// becomes the profile's background pot, the others take the remaining pots
// in increasing index order. potForIndex() tells a caller (or a test) which.
#include <array>
#include <vector>

#include "devices/tek4027/tek4027_encoder.hpp"
#include "devices/tek4027/tek4027_pacing.hpp"
#include "devices/tek4027/tek4027_profile.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4027 {

class Tek4027Driver final : public IndexedSink {
 public:
  // `orientation` applies to an explicit strategy; Shortest tries each.
  explicit Tek4027Driver(ByteSink& sink, Tek4027Profile profile = {},
                         Tek4027Strategy strategy = Tek4027Strategy::Shortest,
                         Tek4027Orientation orientation = Tek4027Orientation::Rows);

  // A serial line's input: when the profile paces the stream with `!REP`
  // requests, end() waits for one reply after each record. Without one (a
  // file), the requests are written and nothing waits.
  void setReplies(Tek4027Replies* replies) { replies_ = replies; }

  int maxColors() const override { return profile_.colors; }
  // Throws lattice::Error(Usage) if the frame is larger than the graphics
  // area or has more colours than the terminal's pots.
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  // Encodes and writes the stream, then flushes the sink (closing it is the
  // caller's business).
  void end() override;

  int potForIndex(PaletteIndex index) const { return potOf_.at(index); }
  const Tek4027StreamStats& stats() const { return stats_; }
  const Tek4027Profile& profile() const { return profile_; }

 private:
  ByteSink& sink_;
  Tek4027Profile profile_;
  Tek4027Strategy strategy_;
  Tek4027Orientation orientation_;
  FrameInfo frame_;
  std::vector<PaletteIndex> pixels_;
  int nextRow_ = -1;  // -1: begin() not called
  std::array<int, 256> potOf_{};
  Tek4027StreamStats stats_;
  Tek4027Replies* replies_ = nullptr;
};

}  // namespace lattice::tek4027
