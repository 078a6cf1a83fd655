#include "render/band_cache.hpp"

#include <algorithm>
#include <utility>

namespace lattice {

BandCache::BandCache(int width, int height, int threads, ShadeRow shadeRow)
    : width_(width), height_(height), threads_(threads), shadeRow_(std::move(shadeRow)) {}

BandCache::~BandCache() = default;

// One thread has no pool to keep busy, so its band is the row asked: a
// consumer that skips rows (the sample pass of --mode sample, every 4th row)
// renders only those, where a band of 8 rendered them all (measured: the
// same 23,432 rays for Plate 6 at 64x64 in both modes). Pixels are the same
// either way (rows are independent).
int BandCache::bandRowsAt(int y0) const {
  // Also: no row is rendered ahead while the consumer reads, so one row is
  // all one thread needs: 2 KiB at 512 wide instead of 16, what the
  // firmware's 128 KiB notices (docs/firmware.md).
  if (threads_ <= 1) return std::min(height_ - y0, 1);
  return std::min(height_ - y0, std::max(1, threads_ * kBandRowsPerThread));
}

// One thread (and the firmware): the band in the caller, row after row.
void BandCache::renderBandHere(int y0) {
  const int rows = bandRowsAt(y0);
  band_.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(width_), 0);
  for (int y = y0; y < y0 + rows; ++y) shadeRow_(y, band_.data() + static_cast<std::size_t>(y - y0) * width_);
  bandStart_ = y0;
  bandRows_ = rows;
}

// Hands the band at y0 to the pool, rows one at a time from a shared counter,
// and returns.
void BandCache::startBandAhead(int y0) {
  const int rows = bandRowsAt(y0);
  ahead_.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(width_), 0);
  aheadStart_ = y0;
  aheadRows_ = rows;
  aheadNext_.store(y0);
  Color18* out = ahead_.data();
  const int y1 = y0 + rows;
  pool_->start(
      [this, out, y0, y1](unsigned) {
        for (int y = aheadNext_.fetch_add(1); y < y1; y = aheadNext_.fetch_add(1))
          shadeRow_(y, out + static_cast<std::size_t>(y - y0) * width_);
      },
      [this, y1] { aheadNext_.store(y1); });
}

// Waits for the band under way and makes it the current one.
void BandCache::takeBandAhead() {
  const int start = std::exchange(aheadStart_, -1);
  pool_->wait();  // rethrows a worker's error
  band_.swap(ahead_);
  bandStart_ = start;
  bandRows_ = aheadRows_;
}

void BandCache::row(int y, std::span<Color18> out) {
  std::lock_guard lock(mutex_);
  if (!inBand(y)) {
    if (threads_ <= 1 || !kHasThreads) {
      renderBandHere(y);
    } else {
      if (!pool_) pool_ = std::make_unique<WorkerPool>(static_cast<unsigned>(threads_));
      // A band ahead that does not hold y is finished and dropped.
      if (aheadStart_ >= 0 && (y < aheadStart_ || y >= aheadStart_ + aheadRows_)) takeBandAhead();
      if (!inBand(y)) {
        if (aheadStart_ < 0) startBandAhead(y);
        takeBandAhead();
      }
      // The next band is rendered while the consumer reads this one; none
      // past the last row.
      const int next = bandStart_ + bandRows_;
      if (next < height_) startBandAhead(next);
    }
  }
  const Color18* src = band_.data() + static_cast<std::size_t>(y - bandStart_) * static_cast<std::size_t>(width_);
  std::copy(src, src + width_, out.begin());
}

}  // namespace lattice
