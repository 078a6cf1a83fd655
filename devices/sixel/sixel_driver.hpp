#pragma once
// The sixel driver: an IndexedSink writing DEC sixel graphics to a ByteSink,
// band by band as the rows arrive. It holds one six-row band (width x 6
// bytes) and the band encoder's per-column arrays (one byte a column for
// each register: at most 256 x 1000), never the frame.
//
// Stream: DCS [P1;P2;P3] q, raster attributes "1;1;W;H (square pixels, the
// picture's size), one `#i;2;r;g;b` per palette entry (register i = palette
// index i, guns in percent), the bands (sixel_band.hpp) separated by `-`,
// then ST. The first band is encoded once it is complete, so the colour
// definitions always come before any sixel.
#include <memory>
#include <string>
#include <vector>

#include "devices/sixel/sixel_band.hpp"
#include "devices/sixel/sixel_profile.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/scanline.hpp"

namespace lattice::sixel {

struct SixelStreamStats {
  std::uint64_t bytes = 0;
  std::uint64_t bands = 0;
  std::uint64_t registers = 0;  // defined
  SixelBandStats band;          // passes and runs over all bands
};

class SixelDriver final : public IndexedSink {
 public:
  explicit SixelDriver(ByteSink& sink, SixelProfile profile = {});
  int maxColors() const override { return profile_.registers; }
  // Throws lattice::Error(Usage) when the frame is larger than the profile's
  // size or has more colours than registers.
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  // Writes the last band and ST, then flushes the sink.
  void end() override;
  const SixelStreamStats& stats() const { return stats_; }
  const SixelProfile& profile() const { return profile_; }

 private:
  void flushBand();
  void put(const std::string& bytes);

  ByteSink& sink_;
  SixelProfile profile_;
  FrameInfo frame_;
  std::vector<PaletteIndex> band_;
  int bandRows_ = 0;
  int nextRow_ = -1;  // -1: begin() not called
  std::unique_ptr<SixelBandEncoder> encoder_;
  std::string out_;
  SixelStreamStats stats_;
};

// The stream's opening: DCS with the profile's parameters, raster
// attributes and the palette's registers.
std::string sixelHeader(const SixelProfile& profile, const FrameInfo& frame);

}  // namespace lattice::sixel
