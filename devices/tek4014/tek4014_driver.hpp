#pragma once
// The 4014 driver: rows of palette indices in, a Tek 4010/4014 graphics
// stream out, one row at a time (no frame is held: O(width) memory).
//
// Method and tunables:
//  - The stream opens with ESC FF (PAGE: erase, alpha mode) and closes with
//    a dark move to xterm's home position for its large characters
//    (0, 2992 in 12-bit units) and US (alpha mode), so what the user types
//    next is text, not coordinates.
//  - The picture sits at the lower-left corner, the origin of Tek
//    addressing: picture pixel (x, row r) is address (x, height - 1 - r),
//    one address unit a pixel.
//  - Each row is dithered (tek4014_dither.hpp), then written in whichever of
//    two forms is shorter for that row: point plot (FS once, then one
//    address per lit dot) or short vectors (per run of lit dots: GS, a dark
//    move to its first dot, a vector to its last; a one-dot run draws a
//    zero-length vector, which is a dot). Both use address compression
//    (tek4014_address.hpp), so a dot in the same 32-unit column band of the
//    same row costs one byte (Lo X) in 10-bit mode.
#include <cstdint>
#include <string>
#include <vector>

#include "devices/tek4014/tek4014_address.hpp"
#include "devices/tek4014/tek4014_dither.hpp"
#include "devices/tek4014/tek4014_profile.hpp"
#include "foundation/byte_sink.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4014 {

struct Tek4014Stats {
  std::uint64_t bytes = 0;
  std::uint64_t dots = 0;        // lit dots drawn
  std::uint64_t pointRows = 0;   // rows sent as point plots
  std::uint64_t vectorRows = 0;  // rows sent as short vectors
  std::uint64_t vectors = 0;     // vectors (runs) in those rows
};

// The 12-bit y of the alpha cursor's home line (xterm: (35 - 1) lines * 88
// units for its large characters).
inline constexpr int kHomeY = 2992;

class Tek4014Driver final : public IndexedSink {
 public:
  explicit Tek4014Driver(ByteSink& sink, Tek4014Profile profile = {});

  int maxColors() const override { return 256; }
  // Throws lattice::Error(Usage) when the frame is larger than the screen.
  void begin(const FrameInfo& frame) override;
  void row(int y, std::span<const PaletteIndex> indices) override;
  void end() override;

  const Tek4014Stats& stats() const { return stats_; }
  const Tek4014Profile& profile() const { return profile_; }

 private:
  enum class Mode { Alpha, Points, Vectors };
  void write(const std::string& bytes);

  ByteSink& sink_;
  Tek4014Profile profile_;
  FrameInfo frame_;
  int nextRow_ = -1;  // -1: begin() not called
  std::vector<RowDither> dither_;  // one, made in begin() (it needs the palette)
  std::vector<std::uint8_t> lit_;
  AddressEncoder encoder_;
  Mode mode_ = Mode::Alpha;
  std::string points_, vectors_;
  Tek4014Stats stats_;
};

}  // namespace lattice::tek4014
