#pragma once
// The Tektronix 4125 driver: an IndexedSink that turns a quantized frame
// into a 4100-series command stream on a ByteSink.
//
// The frame is kept (a byte a pixel) because the stream's set-up depends on
// the whole picture (its most frequent colour is painted once and its runs
// skipped) and because the "shortest" strategy encodes the picture once per
// candidate, counting its bytes, and sends the smallest (encoded once more,
// into the sink: no candidate stream is ever held whole). What the stream may contain is
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
#include "devices/tek4125/tek4125_strategy.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"
#include "foundation/byte_sink.hpp"
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

// 8-bit gun to the terminal's 0..100 percent, rounded to nearest.
constexpr int percentFrom8(unsigned v8) { return static_cast<int>((v8 * 100u + 127u) / 255u); }
// And back, rounded to nearest (what the emulator shows).
constexpr std::uint8_t eightFromPercent(int percent) {
  return static_cast<std::uint8_t>((static_cast<unsigned>(percent) * 255u + 50u) / 100u);
}

class Tek4125Driver final : public IndexedSink {
 public:
  // The profile's strategy= decides the options.
  Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile);
  Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile, Tek4125DriverOptions options);
  int maxColors() const override { return profile_.maxColors(); }
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  // Encodes, writes the stream and flushes the sink.
  void end() override;
  const Tek4125StreamStats& stats() const { return stats_; }

 private:
  // Writes the stream these options give to `sink`.
  void encode(const Tek4125DriverOptions& options, ByteSink& sink, Tek4125StreamStats& stats) const;
  int mostFrequentIndex() const;

  ByteSink& sink_;
  Tek4125Profile profile_;
  Tek4125DriverOptions options_;
  Tek4125StreamStats stats_;
  FrameInfo frame_;
  std::vector<PaletteIndex> pixels_;
  int nextRow_ = 0;
  bool begun_ = false;
};

std::unique_ptr<Tek4125Driver> makeTek4125Driver(ByteSink& sink, const Tek4125Profile& profile);

}  // namespace lattice::tek4125
