#pragma once
// The GPR calls the Apollo driver makes, as an interface: the simulated
// display (gpr_display.hpp) carries them out in memory, the journal
// (gpr_journal.hpp) writes them as bytes to any transport, so the Apollo is a
// byte-stream device like the terminals and its emulator is a decoder.
#include <cstdint>
#include <span>
#include <string>

namespace lattice::apollo {

struct GprDisplayCharacteristics {  // the fields of gpr_$disp_char_t we model
  std::string model;
  int xVisibleSize = 0;
  int yVisibleSize = 0;
  int nPlanes = 0;
  int lutWidthPerPrimary = 0;  // bits per gun in the colour map
  int colorMapEntries = 0;
};

struct GprWindow {  // gpr_$window_t: origin and size in pixels
  int x = 0, y = 0, width = 0, height = 0;
};

class GprCalls {
 public:
  virtual ~GprCalls() = default;
  virtual GprDisplayCharacteristics inqDispCharacteristics() const = 0;
  virtual void acquireDisplay() = 0;
  virtual void releaseDisplay() = 0;
  // Entries start .. start+values.size()-1 take the packed 0xRRGGBB values.
  virtual void setColorMap(int start, std::span<const std::uint32_t> values) = 0;
  // A window of pixel values, row-major, inside the screen.
  virtual void writePixels(std::span<const std::uint32_t> values, const GprWindow& window) = 0;
  virtual void clear(std::uint32_t index) = 0;
};

}  // namespace lattice::apollo
