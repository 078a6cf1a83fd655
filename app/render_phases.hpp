#pragma once
// Where a render's time goes, phase by phase: what `lattice render` prints
// after the total and bench/scaling.sh reads to find the serial fraction.
//
// Method: wall-clock seconds (steady_clock) around each phase. Set-up is the
// scene loaded, its lattices rasterized and the renderer's trees built;
// output is the PNG encoded and written (and, for a device, the emulator
// finished). For a device the quantizer pulls rows from the renderer, which
// traces a band ahead on its own threads, so the two overlap: trace is the
// time the quantizer waited for rows (TimedRowSource), and quantize is the
// rest of the pipeline (histogram, median cut, mapping, and the driver and
// emulator fed row by row).
#include <chrono>
#include <span>

#include "foundation/scanline.hpp"

namespace lattice::app {

struct RenderPhases {
  double setup = 0;
  double trace = 0;
  double quantize = 0;  // 0 for a truecolour picture
  double output = 0;
};

// Seconds since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A row source that adds the time each row took to come to `seconds`.
class TimedRowSource final : public RowSource18 {
 public:
  TimedRowSource(RowSource18& source, double& seconds) : source_(source), seconds_(seconds) {}
  int width() const override { return source_.width(); }
  int height() const override { return source_.height(); }
  void row(int y, std::span<Color18> out) override {
    const auto start = std::chrono::steady_clock::now();
    source_.row(y, out);
    seconds_ += secondsSince(start);
  }

 private:
  RowSource18& source_;
  double& seconds_;
};

}  // namespace lattice::app
