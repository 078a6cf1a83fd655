#pragma once
// A simulated Apollo colour display with the shape of the GPR calls a 1980s
// program made (gpr_$init, gpr_$inq_disp_characteristics, gpr_$acquire_display,
// gpr_$set_color_map, gpr_$write_pixels, gpr_$clear, gpr_$release_display,
// gpr_$terminate), over an indexed framebuffer and a 0xRRGGBB colour map.
// Calls out of order (drawing before init or without the display acquired)
// are bugs in the calling driver and throw lattice::Error(Internal), as GPR
// would return an error status.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "devices/apollo_sim/apollo_profile.hpp"
#include "devices/apollo_sim/gpr_calls.hpp"
#include "foundation/indexed_image.hpp"

namespace lattice::apollo {

// gpr_$display_mode_t. The simulator draws into the same framebuffer in every
// mode; the mode only decides whether acquire/release is required (borrow and
// direct share the screen with the window manager, frame and no_display do not).
enum class GprDisplayMode { Borrow, Direct, Frame, NoDisplay };

class GprDisplay final : public GprCalls {
 public:
  void init(GprDisplayMode mode, const ApolloProfile& profile);
  GprDisplayCharacteristics inqDispCharacteristics() const override;
  void acquireDisplay() override;
  void releaseDisplay() override;
  // Entries start .. start+values.size()-1 take the packed 0xRRGGBB values.
  void setColorMap(int start, std::span<const std::uint32_t> values) override;
  // A window of pixel values, row-major; each value keeps its low `planes`
  // bits, as the bit planes would. The window must lie inside the screen.
  void writePixels(std::span<const std::uint32_t> values, const GprWindow& window) override;
  void clear(std::uint32_t index) override;
  void terminate();

  bool acquired() const { return acquired_; }
  const ApolloProfile& profile() const { return profile_; }
  std::uint32_t pixel(int x, int y) const;
  std::uint32_t colorMapEntry(int index) const;
  // The screen as it looks: framebuffer plus colour map (2^planes entries).
  IndexedImage snapshot() const;

 private:
  void requireDrawable(const char* call) const;

  ApolloProfile profile_;
  GprDisplayMode mode_ = GprDisplayMode::Borrow;
  bool initialized_ = false;
  bool acquired_ = false;
  std::vector<std::uint8_t> framebuffer_;  // at most 8 planes: a byte a pixel
  std::vector<std::uint32_t> colorMap_;
};

// What gpr_$inq_disp_characteristics reports for a display of this profile.
GprDisplayCharacteristics characteristicsOf(const ApolloProfile& profile);

constexpr std::uint32_t packRgb(Rgb8 c) { return std::uint32_t{c.r} << 16 | std::uint32_t{c.g} << 8 | c.b; }
constexpr Rgb8 unpackRgb(std::uint32_t v) {
  return Rgb8{static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
}

}  // namespace lattice::apollo
