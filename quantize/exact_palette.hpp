#pragma once
// A picture that already has few enough colours needs no colour reduction:
// its own colours, exact to the 8-bit level, become the palette. `lattice
// show` uses it for a recorded stream or a quantized PNG, which the median
// cut would only round to 6 bits a channel again, at the cost of a 1 MiB
// histogram, two passes and a search per pixel.
//
// Method: one pass over the pixels with a small open-addressed table of the
// colours met (packed 24-bit keys; 512 slots, so at most half full at 256
// colours), stopping as soon as there are more than maxColors. The palette
// is ordered by falling pixel count (ties: first met), so the most used
// colours get the smallest indices, the shortest register numbers a device
// such as sixel writes.
#include <optional>

#include "foundation/indexed_image.hpp"
#include "foundation/rgb_image.hpp"

namespace lattice::quantize {

// The picture indexed by its own colours, or none when it has more than
// maxColors (1..256) of them.
std::optional<IndexedImage> exactPalette(const RgbImage& picture, int maxColors);

// The same for a picture already indexed (a decoded stream, whose colour map
// may hold unused or repeated colours): exactly exactPalette(toRgbImage(
// picture), maxColors), the same palette in the same order and the same
// indices, from a count per index and a 256-entry map instead of a hash a
// pixel. Indices beyond the colour map leave it to the RGB path (none).
std::optional<IndexedImage> exactPalette(const IndexedImage& picture, int maxColors);

}  // namespace lattice::quantize
