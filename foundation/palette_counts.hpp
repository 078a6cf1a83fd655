#pragma once
// A second face an IndexedSink (foundation/scanline.hpp) may have: told,
// before begin(), how many pixels of the picture each palette entry will
// get. A quantizer that maps every histogram colour to one entry (no
// dithering) knows that, or the sample's share of it, before the first row; a driver
// that needs the picture's most frequent entry up front (the Tek 4125's
// background) can then stream rows instead of keeping the frame
// (devices/tek4125/tek4125_driver.hpp, docs/firmware.md).
//
// Method: a separate interface found by dynamic_cast, so sinks that do not
// care are untouched. Tunables: none.
#include <cstdint>
#include <span>

namespace lattice {

class PaletteCountsSink {
 public:
  virtual ~PaletteCountsSink() = default;
  // Whether paletteCounts() would be used (computing them costs the
  // quantizer a palette search per distinct colour).
  virtual bool wantsPaletteCounts() const = 0;
  // counts[i]: pixels that will get entry i (after a sampled histogram,
  // --mode sample, the sampled pixels that got it: a share to rank entries
  // by, not a total); called just before begin(), for that picture only.
  virtual void paletteCounts(std::span<const std::uint64_t> counts) = 0;
};

}  // namespace lattice
