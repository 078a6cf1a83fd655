#include "lht/raster/raster_estimate.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "foundation/threads.hpp"
#include "lht/raster/rasterize.hpp"

namespace lattice::lht {

namespace {

// What the rasterizer holds for each boundary point besides its hits: the
// point and its faces, its hit list's header (in the rasterizer, then in
// RasterHits, whose lists and starts grow by doubling) and the allocator's
// header of a non-empty list.
constexpr std::uint64_t kPointBytes =
    sizeof(LatticePoint) + 1 + sizeof(std::vector<RasterHit>) + 2 * (sizeof(std::vector<RasterHit>) + sizeof(std::size_t)) + 16;

// splitmix64: a fixed sequence, so the estimate does not change between runs.
std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The box's boundary points, their faces, and the counts that need no tracing.
struct CountedPairs {
  RasterEstimate e;
  std::vector<LatticePoint> points;
  std::vector<std::uint8_t> faces;
};

CountedPairs countPairs(const LatticeBox& box) {
  CountedPairs c;
  RasterEstimate& e = c.e;
  e.cells = box.cells();
  e.pairs = box.pairCountEq13();
  c.points = box.boundaryPoints();
  c.faces.resize(c.points.size());
  std::array<std::uint64_t, 64> perFaces{};  // boundary points by their face mask
  for (std::size_t i = 0; i < c.points.size(); ++i) ++perFaces[c.faces[i] = box.facesOf(c.points[i])];
  e.boundaryPoints = c.points.size();
  for (unsigned a = 0; a < 64; ++a)
    for (unsigned b = 0; b < 64; ++b)
      if (LatticeBox::pairMultiplicity(std::uint8_t(a), std::uint8_t(b)) != 0) {
        e.distinctPairs += perFaces[a] * perFaces[b];
        if (a == b) e.distinctPairs -= perFaces[a];  // p_i = p_o: a point, not a segment
      }
  e.fixedBytes = e.boundaryPoints * kPointBytes;
  return c;
}

// A row's list grows by doubling and is then copied to its exact size: up to
// three times its hits at once, in every thread (`rows` of them).
std::uint64_t rowBytesFor(unsigned rows, double share, std::uint64_t boundaryPoints) {
  const auto rowHits = static_cast<std::uint64_t>(share * double(boundaryPoints)) + 1;
  return rows * 3 * rowHits * RasterEstimate::kHitBytes;
}

}  // namespace

RasterEstimate worstCaseRaster(const LatticeBox& box, unsigned threads) {
  RasterEstimate e = countPairs(box).e;
  e.hits = e.distinctPairs;
  e.rowBytes = rowBytesFor(rasterWorkers(threads, e.boundaryPoints), 1.0, e.boundaryPoints);
  return e;
}

const RasterEstimate& LazyRasterEstimate::sampled() {
  if (!sampled_) sampled_ = estimateRaster(box_, object_, threads_);
  return *sampled_;
}

RasterEstimate estimateRaster(const LatticeBox& box, const LatticeObject& object, unsigned threads,
                              std::uint64_t samples) {
  CountedPairs counted = countPairs(box);
  RasterEstimate& e = counted.e;
  const std::vector<LatticePoint>& points = counted.points;
  const std::vector<std::uint8_t>& faces = counted.faces;

  // The pairs to trace, drawn first and then traced grouped by entry point,
  // so the cull aims one fan per point (lht/raster/cover_cull.hpp) as the
  // rasterizer does instead of testing every piece for every pair; which
  // pairs hit does not depend on the order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> drawn;
  const auto drawPair = [&](std::size_t i, std::size_t j) {
    if (i == j || LatticeBox::pairMultiplicity(faces[i], faces[j]) == 0) return;
    drawn.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
  };
  if (e.distinctPairs <= samples) {
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t j = 0; j < points.size(); ++j) drawPair(i, j);
  } else {
    std::uint64_t state = 1988;
    // Pairs on a common face are drawn and skipped; they are a minority
    // (about a third on a cube), so the bound on draws is never reached.
    for (std::uint64_t draws = 0; drawn.size() < samples && draws < 16 * samples; ++draws) {
      const std::size_t i = nextRandom(state) % points.size(), j = nextRandom(state) % points.size();
      drawPair(i, j);
    }
  }
  // Grouped by a counting sort on the entry point: linear, where a comparison
  // sort of the pairs stood out in the set-up's profile.
  std::vector<std::uint32_t> firstOf(points.size() + 1, 0);
  for (const auto& pair : drawn) ++firstOf[pair.first + 1];
  for (std::size_t i = 0; i < points.size(); ++i) firstOf[i + 1] += firstOf[i];
  std::vector<std::uint32_t> exits(drawn.size());
  for (const auto& [i, j] : drawn) exits[firstOf[i]++] = j;  // firstOf[i] ends where group i + 1 starts
  // Traced on the rasterizer's threads, entry points handed out one at a time
  // as it does: the tracer is shared read-only, each worker aims its own fan,
  // and the hits are a sum, the same whatever the order.
  const PairTracer tracer(box, *object.primitive, object.cover ? &*object.cover : nullptr);
  const unsigned rows = rasterWorkers(threads, points.size());
  std::vector<std::uint64_t> hitsOf(rows, 0);
  std::atomic<std::size_t> next{0};
  const auto work = [&](unsigned w) {
    CoverCull::Fan fan;
    std::uint64_t hits = 0;  // counted here, stored once: neighbouring counters share a cache line
    for (std::size_t i = next.fetch_add(1); i < points.size(); i = next.fetch_add(1)) {
      const std::size_t begin = i == 0 ? 0 : firstOf[i - 1], end = firstOf[i];  // group i, after the sort
      if (begin == end) continue;
      tracer.cull().aim(points[i].toVec(), faces[i], fan);
      for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t j = exits[k];
        RasterHit hit;
        bool traced = false;
        if (tracer.trace(points[i], faces[i], points[j], faces[j], hit, traced, &fan)) ++hits;
      }
    }
    hitsOf[w] = hits;
  };
  runWorkers(rows, work, [&] { next.store(points.size()); });
  for (const std::uint64_t h : hitsOf) e.sampledHits += h;
  e.sampled = drawn.size();
  const double share = e.sampled ? double(e.sampledHits) / double(e.sampled) : 0.0;
  e.hits = std::min(e.distinctPairs, static_cast<std::uint64_t>(share * double(e.distinctPairs) + 0.5));
  e.rowBytes = rowBytesFor(rows, share, e.boundaryPoints);
  return e;
}

}  // namespace lattice::lht
