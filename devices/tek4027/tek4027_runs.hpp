#pragma once
// The geometry of a 4027 picture: the frame as paint-pot numbers, its
// horizontal runs, and polylines that chain runs of one pot down the image.
// No source shows a raster command or the syntax of the 4027's polygon fill,
// so every pixel that differs from the erase colour is drawn by a vector;
// these are the vectors.
#include <cstdint>
#include <vector>

namespace lattice::tek4027 {

// A frame whose pixels are pot numbers (0..7). Row 0 is the top.
struct PotFrame {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pots;  // row-major
  int backgroundPot = 0;           // pixels of this pot are left to !ERA G
  std::uint8_t at(int x, int y) const {
    return pots[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

// A maximal horizontal stretch of one pot on one row, x0 <= x1 inclusive.
struct PotRun {
  int y = 0;
  int x0 = 0;
  int x1 = 0;
  int pot = 0;
};

// Non-background runs of row y, left to right (maximal: adjacent pixels of
// one pot are always merged).
std::vector<PotRun> rowRuns(const PotFrame& frame, int y);

// Painter's spans: stretches of row y that pot `pot` may paint when the pots
// in `coverable` (bit n = pot n) are drawn afterwards and will paint over
// their own pixels. Each span starts and ends on a pixel of `pot`, so it
// never touches the background or a pot drawn earlier. With an empty mask
// these are the rowRuns() of `pot`.
std::vector<PotRun> coverRuns(const PotFrame& frame, int y, int pot, unsigned coverable);

// A drawing order for the non-background pots that makes painter's spans
// few: greedily, the next pot is the one whose choice leaves the fewest spans
// for itself and (estimated with the rest still coverable) for the others.
std::vector<int> layerOrder(const PotFrame& frame);

struct FramePoint {
  int x = 0;
  int y = 0;  // image row, 0 = top
  friend bool operator==(const FramePoint&, const FramePoint&) = default;
};

// Polylines in one pot that together cover exactly the given runs (and no
// other pixel). A run is linked to a run of the same pot on the next row by a
// one-pixel vertical step when the step's column belongs to both runs, so
// the connecting segment never touches a foreign pixel (diagonal steps: see
// ChainOptions). Retracing part of a run is harmless: the pixels are the
// same pot.
struct ChainOptions {
  int maxPoints = 0;          // points in one polyline; 0: no limit (the encoder splits)
  bool enterInterior = true;  // link even when the step lands inside the next run
  // Also step diagonally to column x +- 1: a one-pixel diagonal vector lights
  // just its two end points on any line algorithm, so it is as safe as a
  // vertical step.
  bool diagonalSteps = true;
};
// runsByRow[y]: the runs (or spans) of one pot on row y, left to right.
std::vector<std::vector<FramePoint>> chainRuns(const std::vector<std::vector<PotRun>>& runsByRow,
                                               const ChainOptions& options);

}  // namespace lattice::tek4027
