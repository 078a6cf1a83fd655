#pragma once
// Where a render's time goes, phase by phase: what `lattice render` prints
// after the total and bench/scaling.sh reads to find the serial fraction.
//
// Method: around each phase, wall-clock seconds (steady_clock) and the
// process's CPU seconds (CLOCK_PROCESS_CPUTIME_ID: every thread's), the
// second because on a shared machine other work stretches the wall clock of
// a one-thread run but not its CPU time. Set-up is the scene loaded, its
// lattices rasterized and the renderer's trees built; output is the PNG
// encoded and written (and, for a device, the stream closed and the
// emulator finished). For a device the quantizer pulls rows from the
// renderer, which traces a band ahead on its own threads, so the two
// overlap: trace is the time the quantizer waited for rows (TimedRowSource),
// and quantize is the rest of the pipeline (histogram, median cut, mapping,
// and the driver and emulator fed row by row).
#include <time.h>

#include <chrono>
#include <span>

#include "foundation/scanline.hpp"

namespace lattice::app {

struct PhaseSeconds {
  double wall = 0;
  double cpu = 0;
};

struct RenderPhases {
  PhaseSeconds setup, trace;
  PhaseSeconds quantize;  // zero for a truecolour picture
  PhaseSeconds output;
};

// A phase's clocks, started when made: add() adds what they moved since.
class PhaseTimer {
 public:
  PhaseTimer() : wall_(std::chrono::steady_clock::now()), cpu_(cpuNow()) {}
  void addTo(PhaseSeconds& phase) const {
    phase.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
    phase.cpu += cpuNow() - cpu_;
  }
  static double cpuNow() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
  }

 private:
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

// A row source that adds the time each row took to come to `phase`.
class TimedRowSource final : public RowSource18 {
 public:
  TimedRowSource(RowSource18& source, PhaseSeconds& phase) : source_(source), phase_(phase) {}
  int width() const override { return source_.width(); }
  int height() const override { return source_.height(); }
  void row(int y, std::span<Color18> out) override {
    const PhaseTimer timer;
    source_.row(y, out);
    timer.addTo(phase_);
  }

 private:
  RowSource18& source_;
  PhaseSeconds& phase_;
};

}  // namespace lattice::app
