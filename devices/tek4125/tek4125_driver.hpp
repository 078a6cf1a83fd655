#pragma once
// The Tektronix 4125 driver: an IndexedSink that turns a quantized frame
// into a 4100-series command stream on a ByteSink.
//
// The stream's set-up depends on the whole picture (its most frequent colour
// is painted once and its runs skipped), and the "shortest" strategy encodes
// the picture once per candidate, counting its bytes, and sends the smallest
// (encoded once more, into the sink: no candidate stream is ever held
// whole); so "shortest" and progressive keep the frame (a byte a pixel).
// Every other strategy streams: given each entry's pixel count up front
// (foundation/palette_counts.hpp, from the quantizer's histogram) it writes the
// header at begin() and plans each row as it arrives, the same bytes with
// no frame (the firmware's way, docs/firmware.md). What the stream may contain is
// the profile's form set (tek4125_forms.hpp, strict by default):
//
//   ESC %!0, LV0; strict: KI1, RD 1 <bits>; TM111; strict: TB <colour 0>;
//   TG (one entry a command in strict, the whole palette in one in compact);
//   ESC FF; RU 1 11 <bits>; RS (the whole screen in strict, the picture in
//   compact); one RR painting the picture in the background colour when the
//   clear did not; then per image row the RH + RP raster spans, RL
//   run-length spans and RR rectangles tek4125_rows.hpp chooses.
//
// Bits per pixel are 4 when the picture (plus reserved entries) fits in 16
// colours, else the profile's planes. Strict sends RP only at 4 bits; a
// picture of more colours goes by RL and RR (docs/tek4125.md).
//
// Geometry: the picture is centred on the screen. Tek y grows upwards, so
// image row 0 (the top) goes to the picture's highest screen row.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "devices/tek4125/tek4125_profile.hpp"
#include "devices/tek4125/tek4125_progressive.hpp"
#include "devices/tek4125/tek4125_strategy.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/palette_counts.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4125 {

// What a finished stream cost.
struct Tek4125StreamStats {
  std::uint64_t bytes = 0;
  double seconds = 0.0;  // at the profile's line format
  std::uint64_t rasterWrites = 0;
  std::uint64_t runLengthWrites = 0;
  std::uint64_t rectangleFills = 0;
  std::uint64_t skippedPixels = 0;
  int rasterBits = 0;
  std::string candidate;  // which variant the shortest strategy kept
};

// Lower-left screen pixel of a width x height picture, Tek orientation (y up).
struct Tek4125Placement {
  int left = 0;
  int bottom = 0;
};
Tek4125Placement placePicture(const Tek4125Profile& profile, int width, int height);


class Tek4125Driver final : public IndexedSink, public PaletteCountsSink {
 public:
  // The profile's strategy= decides the options.
  Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile);
  Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile, Tek4125DriverOptions options);
  ~Tek4125Driver() override;
  int maxColors() const override { return profile_.maxColors(); }
  // Asks the quantizer for each entry's pixel count when it streams.
  bool wantsPaletteCounts() const override;
  void paletteCounts(std::span<const std::uint64_t> counts) override;
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  // Encodes, writes the stream and flushes the sink.
  void end() override;
  const Tek4125StreamStats& stats() const { return stats_; }
  // Whether this strategy writes rows as they arrive (no frame kept) when
  // paletteCounts() came before begin(): every strategy but "shortest",
  // unless progressive=on. The bytes are the ones the kept frame would give.
  bool streams() const;
  // Bytes of picture the driver holds between begin() and end(): the frame,
  // or 0 while it streams.
  std::size_t frameBytes() const { return pixels_.size() * sizeof(PaletteIndex); }

 private:
  struct Stream;
  // The header written to `sink`, and the planner ready for row 0.
  std::unique_ptr<Stream> openStream(const Tek4125DriverOptions& options, ByteSink& sink, int backgroundIndex) const;
  void streamRow(Stream& stream, int y, std::span<const PaletteIndex> indices) const;
  void closeStream(Stream& stream, Tek4125StreamStats& stats) const;
  // Writes the stream these options give to `sink`, from the kept frame.
  void encode(const Tek4125DriverOptions& options, ByteSink& sink, Tek4125StreamStats& stats) const;
  int mostFrequentIndex() const;
  // The first of the largest counts.
  static int mostFrequent(std::span<const std::uint64_t> counts);

  ByteSink& sink_;
  Tek4125Profile profile_;
  Tek4125DriverOptions options_;
  Tek4125StreamStats stats_;
  FrameInfo frame_;
  std::vector<PaletteIndex> pixels_;  // the frame, unless streaming
  ProgressivePlan progressive_;       // with progressive=on: covers and drafts, made once for every candidate
  std::unique_ptr<Stream> stream_;    // while streaming
  std::vector<std::uint64_t> counts_;  // from paletteCounts(), for the next begin()
  int nextRow_ = 0;
  bool begun_ = false;
};

std::unique_ptr<Tek4125Driver> makeTek4125Driver(ByteSink& sink, const Tek4125Profile& profile);

}  // namespace lattice::tek4125
