#pragma once
// The Tektronix 4125 driver: an IndexedSink that turns a quantized frame
// into a 4100-series command stream on a ByteSink.
//
// Stream: ESC %!0 (Tek mode), LV0 (hide the dialog area), TM111 (colour
// map in RGB), TG (the palette as 0..100 percent per gun), ESC FF (clear to
// index 0), RU (pixel operations, overwrite, 4 bits per
// pixel when the indices fit, else the profile's planes), RS (a
// viewport around the picture), then per image row: RH beam position and
// RP raster writes; runs the driver decides not to send raw are either
// skipped (background, already on the cleared screen) or drawn with RR
// rectangle fills. docs/tek4125.md explains the choice and its figures.
//
// Geometry: the picture is centred on the screen. Tek y grows upwards, so
// image row 0 (the top) goes to the viewport's highest pixel row.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "devices/tek4125/tek4125_profile.hpp"
#include "devices/tek4125/tek_encoding.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/scanline.hpp"

namespace lattice {

// Which stream-size savings the driver uses (all on by default; the others
// exist to measure what each one buys).
struct Tek4125DriverOptions {
  bool skipBackground = true;  // runs of image index 0 are not sent (the clear painted them)
  bool rectangles = true;      // a long run of one colour may go as RR instead of raster bits
  bool mergeRows = true;       // an RR continued by the same run on the next rows grows instead
};

// What a finished stream cost.
struct Tek4125StreamStats {
  std::uint64_t bytes = 0;
  double seconds = 0.0;  // at the profile's line format
  std::uint64_t rasterWrites = 0;
  std::uint64_t rectangleFills = 0;
  std::uint64_t skippedPixels = 0;
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
  Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile, Tek4125DriverOptions options = {});
  int maxColors() const override { return profile_.maxColors(); }
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  void end() override;
  const Tek4125StreamStats& stats() const { return stats_; }

 private:
  struct Run {
    int start = 0, length = 0;
    int index = 0;  // device colour map index
  };
  // A rectangle not yet sent: rows below may still extend it downwards.
  struct OpenRectangle {
    Run run;
    int topTekRow = 0;
    int rows = 1;
  };
  enum class Way : std::uint8_t { Raster, Skip, Rectangle };

  std::vector<Way> chooseWays(const std::vector<Run>& runs, const std::vector<int>& continuing) const;
  void emitSpan(std::span<const Run> runs, int tekRow);
  void emitRectangle(const OpenRectangle& rect);
  void closeRectangles(std::vector<OpenRectangle>& next);
  void send();

  ByteSink& sink_;
  Tek4125Profile profile_;
  Tek4125DriverOptions options_;
  Tek4125StreamStats stats_;
  tek::XyEncoder xy_;
  tek::Bytes buffer_;
  std::vector<OpenRectangle> open_;  // rectangles of the previous row, by start column
  std::vector<int> openAt_;          // image column -> entry of open_ starting there, or -1
  Tek4125Placement place_;
  int width_ = 0, height_ = 0, paletteSize_ = 0;
  int rasterBits_ = 8;  // bits per pixel of RP data
  int nextRow_ = 0;
  bool begun_ = false;
};

std::unique_ptr<Tek4125Driver> makeTek4125Driver(ByteSink& sink, const Tek4125Profile& profile,
                                                 Tek4125DriverOptions options = {});

}  // namespace lattice
