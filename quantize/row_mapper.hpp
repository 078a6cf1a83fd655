#pragma once
// Maps rows of Color18 to palette indices through an InverseColorMap, with
// optional dithering. Holds O(width) state: Floyd-Steinberg keeps ONE error
// row of (width + 2) x 3 ints (the row being diffused into is written just
// behind the pixel being read, so the current and next rows share it);
// Bayer and no-dither keep nothing, so for them any number of threads may
// map rows at once (the inverse colour map is safe to share).
#include <cstdint>
#include <span>
#include <vector>

#include "foundation/scanline.hpp"
#include "quantize/inverse_colormap.hpp"
#include "quantize/quantize_options.hpp"

namespace lattice::quantize {

class RowMapper {
 public:
  RowMapper(InverseColorMap& map, int width, Dither dither);

  // Rows must come in order y = 0, 1, ... for Floyd-Steinberg (the error row
  // carries state); out.size() == in.size() == width.
  void mapRow(int y, std::span<const Color18> in, std::span<PaletteIndex> out);

  Dither dither() const { return dither_; }

  static std::size_t errorRowBytes(int width) { return (static_cast<std::size_t>(width) + 2) * 3 * sizeof(int); }

 private:
  void mapPlain(std::span<const Color18> in, std::span<PaletteIndex> out);
  void mapFloydSteinberg(int y, std::span<const Color18> in, std::span<PaletteIndex> out);
  void mapBayer(int y, std::span<const Color18> in, std::span<PaletteIndex> out);

  InverseColorMap& map_;
  int width_;
  Dither dither_;
  std::vector<int> errors_;  // Floyd-Steinberg only; sixteenths of a level
  int bayerSpread_ = 0;      // Bayer only: half the palette spacing, 8-bit levels
};

}  // namespace lattice::quantize
