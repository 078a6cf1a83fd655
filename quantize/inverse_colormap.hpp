#pragma once
// Inverse colour map: Color18 -> nearest palette entry (squared distance in
// 8-bit RGB, lowest index on ties), with Heckbert's locally sorted search.
//
// The 64^3 colour cube is split into 16^3 coarse cells of 4x4x4 colours. The
// first time a colour in a coarse cell is asked for, the cell's candidate list
// is built: every entry whose nearest possible distance to the cell is no more
// than the smallest farthest distance of any entry (no other entry can be
// nearest to any colour inside), sorted by that nearest distance. All 64
// colours of the cell are then resolved by walking the list and stopping once
// an entry's nearest distance exceeds the best found. Answers are cached per
// colour in a 2^18-entry table, which is the histogram's own counter array
// handed over after the palette is built (libjpeg's jquant2 reuses its
// histogram the same way), so the map costs no memory beyond the histogram
// plus 4 KiB of "cell resolved" flags. Work is proportional to the colours
// actually present, not to the whole cube.
//
// Any number of threads may call nearest() at once (the pipeline maps bands
// of rows on every thread, quantize/frame_bands.hpp): a coarse cell is
// resolved under a lock, then published by its flag (a release store), and
// every later look-up reads the flag with an acquire load (a plain load on
// x86-64) and the cache with no lock. Whoever resolves a cell writes the
// same answers, so the map is the same whatever the threads' order.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "foundation/scanline.hpp"
#include "foundation/threads.hpp"

namespace lattice::quantize {

class InverseColorMap {
 public:
  static constexpr int kCoarseCells = 16 * 16 * 16;

  // storage: a 2^18-entry array to reuse as the cache (Histogram::releaseStorage);
  // any other size (e.g. empty) makes the map allocate its own.
  explicit InverseColorMap(Palette palette, std::vector<std::uint32_t> storage = {});
  // With no cache (the small histogram's form, docs/firmware.md): each
  // colour is looked up in the whole palette, the same nearest entry with the
  // same tie rule, for O(palette) work a pixel and no 1 MiB table.
  static InverseColorMap uncached(Palette palette);

  // Nearest palette entry; lattice::Error(Internal) with an empty palette or a
  // colour outside 18 bits.
  PaletteIndex nearest(Color18 color) {
    if (color >= kCells) throwBadColor(color);
    if (!cached_) return nearestInPalette(color);
    unsigned coarse = coarseCell(color);
    if (!resolved_[coarse].load(kPublished)) resolveCoarseCell(coarse);
    return static_cast<PaletteIndex>(cache_[color]);
  }

  const Palette& palette() const { return palette_; }
  std::size_t resolvedCoarseCells() const;  // how much of the cube was needed
  static constexpr std::size_t cacheBytes() { return kCells * sizeof(std::uint32_t); }

 private:
  static constexpr std::size_t kCells = std::size_t{1} << 18;
  // One flow of control needs no ordering (a Cortex-M3's acquire is a barrier).
  static constexpr std::memory_order kPublished = kHasThreads ? std::memory_order_acquire : std::memory_order_relaxed;
  static unsigned coarseCell(Color18 c) { return (red6(c) >> 2) << 8 | (green6(c) >> 2) << 4 | (blue6(c) >> 2); }
  [[noreturn]] static void throwBadColor(Color18 color);
  void resolveCoarseCell(unsigned coarse);
  PaletteIndex nearestInPalette(Color18 color) const;
  InverseColorMap(Palette palette, bool cached);

  bool cached_ = true;
  Palette palette_;
  std::vector<std::uint32_t> cache_;
  // Set once a coarse cell's answers are in cache_ (held by pointer: the map stays movable).
  std::unique_ptr<std::atomic<std::uint8_t>[]> resolved_;
  std::unique_ptr<Mutex> resolving_;
  // Scratch reused by every coarse cell, under resolving_: (nearest distance, entry) pairs.
  std::vector<std::pair<int, int>> candidates_;
};

}  // namespace lattice::quantize
