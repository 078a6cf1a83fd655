#pragma once
// The band cache behind Renderer::row() (render/renderer.hpp): a consumer
// that reads one row at a time still keeps every core busy.
//
// Method: rows are rendered a band at a time and the band is kept. With one
// thread (or none: the firmware) the band is one row, rendered in the
// caller when asked (so a consumer that skips rows renders only those). With more, a worker pool started on first
// use renders the band after the current one while the consumer reads this
// one, handing rows out one at a time from a shared counter (which thread
// shades a row never changes its pixels); a band ahead that does not hold
// the row asked (rows out of order, a second pass from the top) is finished
// and dropped.
//
// Tunables: kBandRowsPerThread rows per thread in a band (with two or more
// threads): enough that the
// rows' uneven costs even out before the band's last row (a thread idles
// until then), few enough that a streaming consumer sees rows early.
#include <atomic>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "foundation/scanline.hpp"
#include "foundation/threads.hpp"

namespace lattice {

class BandCache {
 public:
  static constexpr int kBandRowsPerThread = 8;
  // shadeRow(y, out): writes row y's `width` pixels to out; called from the
  // pool's threads at once when threads > 1.
  using ShadeRow = std::function<void(int y, Color18* out)>;

  BandCache(int width, int height, int threads, ShadeRow shadeRow);
  ~BandCache();
  BandCache(const BandCache&) = delete;
  BandCache& operator=(const BandCache&) = delete;

  // Row y (0 <= y < height) into out (width pixels); safe from several
  // threads at once (one at a time gets in).
  void row(int y, std::span<Color18> out);

 private:
  int bandRowsAt(int y0) const;
  bool inBand(int y) const { return y >= bandStart_ && y < bandStart_ + bandRows_; }
  void renderBandHere(int y0);
  void startBandAhead(int y0);
  void takeBandAhead();

  int width_, height_, threads_;
  ShadeRow shadeRow_;
  // Rows [bandStart_, bandStart_ + bandRows_) are in band_. The pool renders
  // the next band into ahead_ (aheadStart_ >= 0 while it is under way).
  Mutex mutex_;
  int bandStart_ = -1;
  int bandRows_ = 0;
  std::vector<Color18> band_;
  int aheadStart_ = -1;
  int aheadRows_ = 0;
  std::vector<Color18> ahead_;
  std::atomic<int> aheadNext_{0};
  // Last, so it is stopped (waiting for its band) before what it writes goes.
  std::unique_ptr<WorkerPool> pool_;
};

}  // namespace lattice
