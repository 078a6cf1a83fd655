#pragma once
// Drawing on the emulated screen in Tek orientation (pixel y = 0 is the
// bottom row, as the terminal counts) while the framebuffer, like every
// IndexedImage, stores the top row first. Everything is clipped: streams
// can ask for any coordinate.
#include <cstdint>
#include <span>

#include "pipeline/indexed_image.hpp"

namespace lattice::tek {

// The pixel at (px, py), or nullptr when it is off the screen.
inline PaletteIndex* pixelAt(IndexedImage& screen, int px, int py) {
  if (px < 0 || py < 0 || px >= screen.width || py >= screen.height) return nullptr;
  return &screen.at(px, screen.height - 1 - py);
}

// Bresenham line between pixel centres, both ends drawn.
void drawLine(IndexedImage& screen, int px0, int py0, int px1, int py1, PaletteIndex index);

// Even-odd fill of a polygon (x, y pairs in pixels, fractions allowed): a
// pixel is inside when its centre is. Work is O(rows * points).
void fillPolygon(IndexedImage& screen, std::span<const double> xy, PaletteIndex index);
// What fillPolygon will cost, in pixel units (devices/work_budget.hpp): per
// row it crosses, one unit per edge tested and one per pixel it may fill.
std::uint64_t fillPolygonWork(const IndexedImage& screen, std::span<const double> xy);

}  // namespace lattice::tek
