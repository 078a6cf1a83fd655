#pragma once
// The emulated screens' one drawing surface, shared by every terminal
// emulator: Tek orientation (pixel y = 0 is the bottom row, as the terminals
// count) over an IndexedImage that stores the top row first.
//
// Method: everything is clipped, and a primitive costs what its visible part
// costs: a line visits only the steps that can land on the screen (a vector
// 130,000 pixels long costs no more than one across it), a polygon only the
// rows it covers. Streams may ask for any coordinate.
//
// Lines are a DDA between pixel centres, both ends drawn, point i of n at
// start + i * delta / n rounded to nearest with ties away from the start:
// that is exactly the pixel set of the integer Bresenham walk (checked
// exhaustively for endpoints in [-6, 6] and on 200,000 random lines in
// [-300, 300]), so either way of thinking about a line gives the same picture.
#include <cstdint>
#include <span>

#include "foundation/indexed_image.hpp"

namespace lattice::devices {

// The pixel at (px, py), or nullptr when it is off the screen.
inline PaletteIndex* pixelAt(IndexedImage& screen, long px, long py) {
  if (px < 0 || py < 0 || px >= screen.width || py >= screen.height) return nullptr;
  return &screen.at(static_cast<int>(px), static_cast<int>(screen.height - 1 - py));
}

// A line between pixel centres, both ends drawn, clipped to the screen.
void drawLine(IndexedImage& screen, long px0, long py0, long px1, long py1, PaletteIndex index);
// The steps drawLine visits for that line (its work, devices/work_budget.hpp).
std::uint64_t lineWork(const IndexedImage& screen, long px0, long py0, long px1, long py1);

// Even-odd fill of a polygon (x, y pairs in pixels, fractions allowed): a
// pixel is inside when its centre is. Work is O(rows covered * (points +
// width)): each row is swept, never sorted.
void fillPolygon(IndexedImage& screen, std::span<const double> xy, PaletteIndex index);
// What fillPolygon will cost, in pixel units: per row it covers, one unit per
// edge tested and one per pixel it may fill.
std::uint64_t fillPolygonWork(const IndexedImage& screen, std::span<const double> xy);

}  // namespace lattice::devices
