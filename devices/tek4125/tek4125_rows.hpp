#pragma once
// Method: per image row, a dynamic programme over the row's runs of equal
// colour chooses how each run is drawn: skipped (the background colour,
// already painted, or, when the caller says what the screen shows, any run
// already there: the progressive stream's covers and drafts), an RR
// rectangle (held open while the rows below repeat the same run, so one RR
// covers them all), inside an RP raster span, or
// inside an RL run-length span. After each run the beam is in one of three
// states (outside a span, in RP, in RL); starting or switching a span costs
// its header, which the form set decides (an RH before each span when the
// beam is not trusted to continue). Linear in the runs; optimal for the
// estimated costs. Tunables: the per-command byte estimates below, which
// follow the encodings in tek4125_encoding.hpp.
#include <cstdint>
#include <span>
#include <vector>

#include "devices/tek4125/tek4125_strategy.hpp"
#include "devices/tek4125/tek4125_writer.hpp"

namespace lattice::tek4125 {

struct Tek4125RowLayout {
  int left = 0, bottom = 0;          // screen pixel of the picture's lower-left corner
  int viewportX = 0, viewportY = 0;  // lower-left corner of the pixel viewport (RH is relative to it)
  int width = 0, height = 0;
  int bits = 4;                      // RU bits per pixel
  int background = -1;               // device index skipped when skipping, -1 none
  bool raster = true;                // RP allowed at this depth
  bool runLength = false;            // RL allowed
};

struct Tek4125RowStats {
  std::uint64_t rasterWrites = 0, runLengthWrites = 0, rectangleFills = 0, skippedPixels = 0;
};

class Tek4125RowPlanner {
 public:
  Tek4125RowPlanner(Tek4125Writer& out, const Tek4125RowLayout& layout, const Tek4125DriverOptions& options);
  // Image row y (0 = top) of device colour indices. With `shown` (what
  // each pixel of the row shows already, device indices), a run is skipped
  // where it shows already, whatever its colour; without, where it is the
  // layout's background colour (painted once under the whole picture).
  void row(int y, std::span<const int> indices, std::span<const int> shown = {});
  // Sends the rectangles still open.
  void finish();
  const Tek4125RowStats& stats() const { return stats_; }
  int width() const { return layout_.width; }

 private:
  struct Run {
    int start = 0, length = 0, index = 0;
  };
  struct OpenRectangle {
    Run run;
    int topScreenRow = 0;
    int rows = 1;
  };
  enum class Way : std::uint8_t { Skip, Rectangle, Raster, Runs };

  std::vector<Way> chooseWays(const std::vector<Run>& runs, const std::vector<int>& continuing,
                              const std::vector<bool>& skippable) const;
  double runCodeBytes(const Run& r) const;
  void emitRaster(std::span<const Run> runs, int screenRow, bool positioned);
  void emitRuns(std::span<const Run> runs, int screenRow, bool positioned);
  void beamTo(int x, int screenRow);
  void emitRectangle(const OpenRectangle& rect);
  void closeRectangles(std::vector<OpenRectangle>& next);

  Tek4125Writer& out_;
  Tek4125RowLayout layout_;
  Tek4125DriverOptions options_;
  Tek4125RowStats stats_;
  int maxRunLength_ = 1;
  std::vector<OpenRectangle> open_;
  std::vector<int> openAt_;  // image column -> entry of open_ starting there, or -1
};

}  // namespace lattice::tek4125
