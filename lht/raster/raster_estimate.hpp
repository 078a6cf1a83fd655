#pragma once
// What rasterizing a lattice will hold, known before it starts: the number
// of (p_i, p_o) pairs from the lattice's cell counts (eq. 1.3), the share of
// them that hit the object from a sample, and the bytes the rasterizer keeps
// for them (lht/raster/rasterize.hpp). A memory budget refuses a lattice from
// this before any work (docs/memory.md); the rasterizer's running count
// (RasterOptions::maxHits) stops one the sample underestimated.
//
// Method: the pairs the rasterizer considers are the ordered pairs p_i != p_o
// that eq. 1.3 counts with a non-zero multiplicity; their number follows from
// how many boundary points lie on each combination of faces, and it bounds
// the entries. kEstimateSamples of them, drawn uniformly by a fixed-seed
// generator (so every run estimates the same), or all of them for a small
// lattice, are traced by the rasterizer's own PairTracer, grouped by entry
// point so each point's pairs share one fan of the cover cull as the
// rasterizer's do (lht/raster/cover_cull.hpp), instead of testing every
// cover piece for every drawn pair; on the rasterizer's threads, since the
// count of hits does not depend on which thread traced which pair.
#include <array>
#include <cstdint>
#include <optional>

#include "lht/grid/lattice_box.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/raster_hits.hpp"

namespace lattice::lht {

// 16,384 traced pairs take a few milliseconds; the hit share they give is
// within a few per cent of the whole for the example lattices (1 % of pairs
// hitting: +-8 % at one standard deviation).
inline constexpr std::uint64_t kEstimateSamples = 16384;

struct RasterEstimate {
  std::array<int, 3> cells{};
  std::uint64_t boundaryPoints = 0;  // P
  std::uint64_t pairs = 0;           // N_lp by eq. 1.3 (with its multiplicities)
  std::uint64_t distinctPairs = 0;   // the distinct pairs rasterized: no more entries than these
  std::uint64_t sampled = 0;         // pairs traced for the estimate
  std::uint64_t sampledHits = 0;     // of them, hits
  std::uint64_t hits = 0;            // expected entries: distinctPairs x sampledHits / sampled
  std::uint64_t fixedBytes = 0;      // the rasterizer's per-point arrays, whatever the hits
  std::uint64_t rowBytes = 0;        // the rows traced at once, their lists grown by doubling
  static constexpr std::uint64_t kHitBytes = sizeof(RasterHit);

  // What the rasterizer holds with `n` hits. The lists' allocator rounding
  // and fragmentation add 2-3 % of the hits' bytes (measured on spheres of
  // 30 and 31 cells a side, docs/memory.md): a sixteenth is allowed.
  std::uint64_t bytesFor(std::uint64_t n) const { return fixedBytes + rowBytes + n * kHitBytes + n * kHitBytes / 16; }
};

// `threads`: the rasterizer's (0: all hardware threads).
RasterEstimate estimateRaster(const LatticeBox& box, const LatticeObject& object, unsigned threads,
                              std::uint64_t samples = kEstimateSamples);

// The estimate's bound, without tracing: the counts estimateRaster gives and
// every distinct pair a hit. No sample can expect more, so whatever fits
// with it fits with any sample (app/memory_plan.hpp admitRaster).
RasterEstimate worstCaseRaster(const LatticeBox& box, unsigned threads);

// What an admission is shown: the bound at once, the sampled estimate traced
// on the first ask only, since a lattice whose worst case fits the budget
// needs no sample (most renders: the default budget is half the RAM).
class LazyRasterEstimate {
 public:
  LazyRasterEstimate(const LatticeBox& box, const LatticeObject& object, unsigned threads)
      : box_(box), object_(object), threads_(threads), worstCase_(worstCaseRaster(box, threads)) {}
  const RasterEstimate& worstCase() const { return worstCase_; }
  const RasterEstimate& sampled();
  bool wasSampled() const { return sampled_.has_value(); }

 private:
  const LatticeBox& box_;
  const LatticeObject& object_;
  unsigned threads_;
  RasterEstimate worstCase_;
  std::optional<RasterEstimate> sampled_;
};

}  // namespace lattice::lht
