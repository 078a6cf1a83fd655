#pragma once
// Rasterization (thesis sec. 2.1): for every entry point p_i on the lattice
// box and every exit point p_o, trace the segment p_i + (p_o - p_i) s,
// s in [0, 1], against the exact object and keep the hit closest to p_i.
// Given a cover of the object (lht/raster/object_cover.hpp), a pair whose segment
// stays clear of it is a miss without a trace (lht/raster/cover_cull.hpp); the
// pairs that may touch are traced as without it, so the table is the same.
// The exit points a row visits are the cull's candidates
// (lht/raster/exit_candidates.hpp); where the object is a union of parts, one
// a piece of its cover (a polyline's capsules: lht/raster/lattice_object.hpp),
// a segment is traced against the parts it passes near, with the union's
// answer to the bit (docs/lattices.md, "Tracing a polyline through its capsules").
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "lht/raster/cover_cull.hpp"
#include "lht/grid/lattice_box.hpp"
#include "lht/raster/lattice_object.hpp"
#include "lht/raster/object_cover.hpp"
#include "lht/raster/raster_hits.hpp"
#include "render/shapes/primitive.hpp"

namespace lattice::lht {

struct RasterStats {
  std::uint64_t pairs = 0;  // N_lp: ordered face pairs, as eq. 1.3 counts them (with duplicates)
  std::uint64_t hits = 0;   // N_iz: the same pairs that hit the object
  std::uint64_t distinctPairs = 0;  // distinct (p_i, p_o) with p_i != p_o that eq. 1.3 counts
  std::uint64_t traced = 0;         // segments actually traced (the rest provably miss)
  double buildMs = 0.0;
};

struct RasterResult {
  RasterHits hits;  // one per distinct hitting (p_i, p_o), in a deterministic order
  RasterStats stats;
};

struct RasterOptions {
  unsigned threads = 0;     // 0: all hardware threads
  bool progress = true;     // a progress bar on stderr (when it is a terminal)
  // A segment passing within this distance (in cells) of the surface counts
  // as a hit: the object is taken as a closed set, so grazing segments hit.
  // It must stay far below the smallest non-zero clearance of lattice
  // segments (~1e-5 cells for a 255-cell lattice) to add only true tangents.
  double grazeTolerance = 1e-7;
  // The running count: the most hits held before the rasterizer stops and
  // throws RasterHitLimit (a memory budget's room, app/render_budget.hpp).
  // Counted a boundary point's row at a time.
  std::uint64_t maxHits = UINT64_MAX;
};

// The workers rasterizing `points` entry points on `threads` (0: all hardware
// threads): never more than there are points. The estimate sizes its rows by it.
unsigned rasterWorkers(unsigned threads, std::size_t points);

// Thrown when the hits pass RasterOptions::maxHits; the caller says why.
class RasterHitLimit : public std::runtime_error {
 public:
  RasterHitLimit(std::uint64_t held, std::uint64_t done, std::uint64_t all)
      : std::runtime_error("the rasterizer's hits passed their limit"), hits(held), pointsDone(done), points(all) {}
  std::uint64_t hits;        // held when it stopped
  std::uint64_t pointsDone;  // entry points whose rows were traced (of `points`)
  std::uint64_t points;
};

// `object` is in object coordinates; box says how they map to lattice ones.
// `cover` (object coordinates, optional) contains the object: pairs whose
// segment stays clear of it are misses without a trace (lht/raster/cover_cull.hpp);
// the result is the same with or without it.
RasterResult rasterize(const LatticeBox& box, const Primitive<double>& object, const RasterOptions& options = {});
RasterResult rasterize(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
                       const RasterOptions& options = {});
// With the object's parts (null: none): the same result again.
RasterResult rasterize(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
                       const ObjectParts* parts, const RasterOptions& options);
// A lattice object's primitive, with its cover when it has one.
RasterResult rasterize(const LatticeBox& box, const LatticeObject& object, const RasterOptions& options = {});

// One pair's answer, exactly as rasterize() gives it: the rasterizer and the
// on-demand table (lht/table/on_demand_table.hpp) share it, so an entry built on
// demand has the bytes the precomputed table would hold.
class PairTracer {
 public:
  PairTracer(const LatticeBox& box, const Primitive<double>& object, double grazeTolerance = RasterOptions{}.grazeTolerance);
  // With a cover of the object (object coordinates; null: none): the same
  // answers, fewer traces.
  PairTracer(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
             double grazeTolerance = RasterOptions{}.grazeTolerance);
  // With the object's parts too (null: none; lht/raster/lattice_object.hpp),
  // which traceCandidate asks in place of the object where the cover's
  // pieces are theirs: the same answers, fewer capsules asked.
  PairTracer(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
             const ObjectParts* parts, double grazeTolerance);
  // The hit of the segment from `in` to `out` (points on the box's surface),
  // with its unit normal; false for a miss, including the pairs rasterize()
  // never traces (a shared face, a segment missing the object's box).
  bool trace(const LatticePoint& in, const LatticePoint& out, RasterHit& hit) const;
  // The same for pairs whose faces are known (the rasterizer's inner loop).
  // `fan`: the cull's fan aimed from `in` (CoverCull::aim), shared by the
  // pairs leaving one point; null: the cull tests the pair alone.
  bool trace(const LatticePoint& in, std::uint8_t facesIn, const LatticePoint& out, std::uint8_t facesOut,
             RasterHit& hit, bool& traced, const CoverCull::Fan* fan = nullptr) const;
  // The same for a pair sharing no face that the cull let through (or that
  // has no cull to pass): the pair is traced unless it misses the object's box.
  bool traceUnculled(const LatticePoint& in, const LatticePoint& out, RasterHit& hit, bool& traced) const;
  // The same for an exit point of the fan's candidates (lht/raster/exit_candidates.hpp)
  // sharing no face with fan.p's point `in`: the cull's exact test on the
  // pieces whose rectangles hold it, then the trace (an active cull only).
  bool traceCandidate(const LatticePoint& in, const LatticePoint& out, const CoverCull::Fan& fan,
                      std::uint64_t pieces, RasterHit& hit, bool& traced) const;
  const CoverCull& cull() const { return cull_; }

 private:
  bool traceClosed(const Vec3d& from, const Vec3d& to, double& s, Vec3d& normal) const;
  bool clipsBounds(const Vec3d& from, const Vec3d& to) const;
  bool nearestPart(const Vec3d& from, const Vec3d& to, CoverCull::Near* near, std::size_t count, double& s,
                   Vec3d& normal) const;

  const LatticeBox& box_;
  const Primitive<double>& object_;
  double grazeTolerance_;
  Mat4d latticeToObject_{1.0};
  Bounds<double> bounds_;
  CoverCull cull_;
  // The object's parts by cover piece, where every piece is one part's; empty: none.
  std::vector<const Primitive<double>*> parts_;
};

}  // namespace lattice::lht
