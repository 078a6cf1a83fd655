#pragma once
// The terminal's screen drawn in the user's terminal as sixels, redrawing
// only what changed.
//
// Method:
//  * The screen is scaled to fit the text area above the lines kept for the
//    dialog area and the status line, never enlarged, and never wider than
//    kMaxViewWidth (xterm's maxGraphicSize default is 1000x1000 and it
//    refuses a larger raster), by nearest neighbour: every pixel shown is a
//    pixel of the screen, so a capture of the host compares with the
//    emulator's picture at the scale shown.
//  * The view is cut into bands one text row high: a sixel picture starts at
//    the text cursor, so a band is the smallest piece that can be drawn
//    again in place (CUP to its row, then one DCS picture of its pixels).
//    update() compares the new view with the one drawn last, band by band,
//    and sends each run of changed bands as one picture (a run shares one
//    palette, written once).
//  * A picture defines only the registers its pixels use (renumbered from
//    0); where they are more than the terminal has (XTSMGRAPHICS), the most
//    used colours keep a register and each other colour takes the nearest
//    of them. The encoder is the project's sixel driver (devices/sixel/).
#include <cstdint>
#include <string>
#include <vector>

#include "foundation/indexed_image.hpp"

namespace lattice::app {

inline constexpr int kMaxViewWidth = 1000;
// Text rows below the picture: the dialog area's last lines and the status line.
inline constexpr int kTextRowsBelow = 3;

struct ViewGeometry {
  int columns = 80, rows = 24;             // the host's text area
  int cellWidth = 10, cellHeight = 20;     // pixels of one text cell
  int registers = 16;                      // colour registers a picture may use
};

struct ViewStats {
  std::uint64_t redraws = 0;      // update() calls that sent something
  std::uint64_t bytes = 0;        // sixel bytes sent in all
  std::uint64_t bandsDrawn = 0;   // bands sent in all
  std::uint64_t lastBytes = 0;    // bytes of the last redraw that sent something
};

class SixelView {
 public:
  SixelView(const ViewGeometry& host, int screenWidth, int screenHeight);
  // The bytes that bring the host's picture from what was drawn last to
  // `screen` (empty: nothing changed). The first call draws every band.
  std::string update(const IndexedImage& screen);
  // Every band of `screen`, as if nothing had been drawn: a full frame's
  // bytes, for comparison with a redraw's.
  std::string fullFrame(const IndexedImage& screen);
  int width() const { return width_; }
  int height() const { return height_; }
  int textRows() const { return bands_; }  // text rows the picture covers
  int screenWidth() const { return screenWidth_; }
  int screenHeight() const { return screenHeight_; }
  const ViewStats& stats() const { return stats_; }
  // The view as last drawn: what a capture of the host should show.
  IndexedImage shown() const;

 private:
  void scale(const IndexedImage& screen);
  std::string drawBands(int first, int last);  // [first, last)

  ViewGeometry host_;
  int screenWidth_, screenHeight_;
  int width_ = 0, height_ = 0, bands_ = 0;
  std::vector<int> sourceX_, sourceY_;  // view pixel -> screen pixel
  std::vector<PaletteIndex> view_, drawn_;
  Palette palette_, drawnPalette_;
  bool drawnAny_ = false;
  ViewStats stats_;
};

}  // namespace lattice::app
