#pragma once
// The Apollo driver: an IndexedSink that draws a quantized picture through
// GPR calls, on the simulated display or into a journal (gpr_calls.hpp). The picture is centred on the screen (odd leftovers go to the
// right and bottom); the border is cleared to black, using a spare colour map
// entry when the palette leaves one and otherwise the palette entry nearest
// black. A picture larger than the screen is refused with lattice::Error(Usage)
// rather than silently cropped.
#include <cstdint>
#include <vector>

#include "devices/apollo_sim/gpr_calls.hpp"
#include "foundation/scanline.hpp"

namespace lattice::apollo {

class ApolloDriver final : public IndexedSink {
 public:
  // The display must be initialised (gpr_$init) and outlive the driver.
  explicit ApolloDriver(GprCalls& display);
  int maxColors() const override;
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  void end() override;

  int originX() const { return originX_; }
  int originY() const { return originY_; }

 private:
  GprCalls& display_;
  FrameInfo frame_;
  int originX_ = 0, originY_ = 0;
  std::vector<std::uint32_t> rowValues_;  // one row of gpr_$pixel_value_t
};

}  // namespace lattice::apollo
