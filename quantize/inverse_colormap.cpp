#include "quantize/inverse_colormap.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <climits>

#include "quantize/median_cut.hpp"
#include "foundation/error.hpp"

namespace lattice::quantize {

InverseColorMap::InverseColorMap(Palette palette, bool cached) : cached_(cached), palette_(std::move(palette)) {
  if (palette_.empty()) throw Error(ErrorKind::Internal, "inverse colour map: the palette is empty");
  if (palette_.size() > 256)
    throw Error(ErrorKind::Internal, fmt::format("inverse colour map: {} palette entries, at most 256", palette_.size()));
}

InverseColorMap::InverseColorMap(Palette palette, std::vector<std::uint32_t> storage)
    : InverseColorMap(std::move(palette), true) {
  cache_ = std::move(storage);
  if (cache_.size() != kCells) cache_.assign(kCells, 0);
  resolved_ = std::make_unique<std::atomic<std::uint8_t>[]>(kCoarseCells);  // value-initialised: none resolved
  resolving_ = std::make_unique<Mutex>();
  candidates_.reserve(palette_.size());
}

InverseColorMap InverseColorMap::uncached(Palette palette) { return InverseColorMap(std::move(palette), false); }

PaletteIndex InverseColorMap::nearestInPalette(Color18 color) const {
  return static_cast<PaletteIndex>(
      nearestEntry(expand6to8(red6(color)), expand6to8(green6(color)), expand6to8(blue6(color)), palette_));
}

void InverseColorMap::throwBadColor(Color18 color) {
  throw Error(ErrorKind::Internal, fmt::format("inverse colour map: {:#x} is not an 18-bit colour", color));
}

std::size_t InverseColorMap::resolvedCoarseCells() const {
  if (!resolved_) return 0;
  std::size_t n = 0;
  for (int i = 0; i < kCoarseCells; ++i) n += resolved_[static_cast<std::size_t>(i)].load(kPublished) != 0;
  return n;
}

void InverseColorMap::resolveCoarseCell(unsigned coarse) {
  std::lock_guard lock(*resolving_);
  if (resolved_[coarse].load(std::memory_order_relaxed)) return;  // another thread resolved it while we waited
  // The cell's corners in 6-bit and 8-bit units.
  std::array<unsigned, 3> base6{(coarse >> 8) * 4, ((coarse >> 4) & 15u) * 4, (coarse & 15u) * 4};
  std::array<int, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = expand6to8(base6[a]);
    hi[a] = expand6to8(base6[a] + 3);
  }
  auto channelOf = [](Rgb8 c, int a) { return a == 0 ? int(c.r) : a == 1 ? int(c.g) : int(c.b); };

  // Bound: no colour in the cell is farther than minFarthest from its nearest entry.
  int minFarthest = INT_MAX;
  std::vector<int> nearestDistance(palette_.size());
  for (std::size_t i = 0; i < palette_.size(); ++i) {
    int nearestD = 0, farthestD = 0;
    for (int a = 0; a < 3; ++a) {
      int v = channelOf(palette_[i], a);
      int below = v < lo[a] ? lo[a] - v : 0;
      int above = v > hi[a] ? v - hi[a] : 0;
      int gap = below + above;
      nearestD += gap * gap;
      int far = std::max(std::abs(v - lo[a]), std::abs(v - hi[a]));
      farthestD += far * far;
    }
    nearestDistance[i] = nearestD;
    minFarthest = std::min(minFarthest, farthestD);
  }
  candidates_.clear();
  for (std::size_t i = 0; i < palette_.size(); ++i)
    if (nearestDistance[i] <= minFarthest) candidates_.emplace_back(nearestDistance[i], int(i));
  std::sort(candidates_.begin(), candidates_.end());  // by distance, then index

  for (unsigned dr = 0; dr < 4; ++dr)
    for (unsigned dg = 0; dg < 4; ++dg)
      for (unsigned db = 0; db < 4; ++db) {
        Color18 c = packColor18(base6[0] + dr, base6[1] + dg, base6[2] + db);
        int r = expand6to8(red6(c)), g = expand6to8(green6(c)), b = expand6to8(blue6(c));
        int best = -1, bestDistance = INT_MAX;
        for (auto [bound, entry] : candidates_) {
          if (bound > bestDistance) break;  // sorted: nothing later can be nearer
          int d = distanceSquared(r, g, b, palette_[entry]);
          if (d < bestDistance || (d == bestDistance && entry < best)) {
            bestDistance = d;
            best = entry;
          }
        }
        cache_[c] = static_cast<std::uint32_t>(best);
      }
  resolved_[coarse].store(1, kHasThreads ? std::memory_order_release : std::memory_order_relaxed);
}

}  // namespace lattice::quantize
