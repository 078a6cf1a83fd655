#include "lht/raster/rasterize.hpp"

#include <algorithm>
#include <bit>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>

#include "foundation/progress.hpp"
#include "foundation/threads.hpp"
#include "lht/raster/exit_candidates.hpp"

namespace lattice::lht {

namespace {

// Traces one segment in object coordinates. The segment's ray keeps s as its
// parameter (an affine map preserves t), so the hit's t is s directly.
bool traceSegment(const Primitive<double>& object, const Mat4d& latticeToObject, const Vec3d& from,
                  const Vec3d& to, double& s, Vec3d& normal) {
  const Ray<double> lattice{from, to - from};
  const Ray<double> ray = lattice.transformed(latticeToObject);
  Hit<double> hit;
  if (!object.firstHit(ray, 0.0, 1.0, hit)) return false;
  s = hit.t;
  normal = hit.normal;
  return true;
}

}  // namespace

PairTracer::PairTracer(const LatticeBox& box, const Primitive<double>& object, double grazeTolerance)
    : PairTracer(box, object, nullptr, grazeTolerance) {}

PairTracer::PairTracer(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
                       double grazeTolerance)
    : PairTracer(box, object, cover, nullptr, grazeTolerance) {}

PairTracer::PairTracer(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
                       const ObjectParts* parts, double grazeTolerance)
    : box_(box), object_(object), grazeTolerance_(grazeTolerance), latticeToObject_(box.latticeToObject()) {
  if (cover) cull_ = CoverCull(cover->mapped(box.objectToLattice()), box.cells());
  // Piece k must be part k's: the cover holds the parts' capsules and nothing else.
  if (parts && cull_.active() && cover->boxes.empty() && parts->parts.size() == cover->capsules.size())
    parts_ = parts->parts;
  // The object's box in lattice coordinates, grown by the graze tolerance:
  // a segment that misses it cannot touch the object.
  const Bounds<double>& b = object.bounds();
  if (b.isFinite() && !b.empty()) {
    bounds_ = transformBounds(b, box.objectToLattice());
    bounds_.lo -= Vec3d(2 * grazeTolerance);
    bounds_.hi += Vec3d(2 * grazeTolerance);
  } else {
    bounds_ = Bounds<double>::infinite();
  }
}

bool PairTracer::trace(const LatticePoint& in, const LatticePoint& out, RasterHit& hit) const {
  bool traced = false;
  return in != out && trace(in, box_.facesOf(in), out, box_.facesOf(out), hit, traced);
}

bool PairTracer::trace(const LatticePoint& in, std::uint8_t facesIn, const LatticePoint& out, std::uint8_t facesOut,
                       RasterHit& hit, bool& traced, const CoverCull::Fan* fan) const {
  traced = false;
  // Points sharing a face span a segment inside that face, and the object
  // lies at least lambda/2 inside the box: a certain miss.
  if (facesIn & facesOut) return false;
  const Vec3d from = in.toVec(), to = out.toVec();
  if (!(fan ? cull_.mayTouch(*fan, to, facesOut) : cull_.mayTouch(from, to))) return false;
  return traceUnculled(in, out, hit, traced);
}

bool PairTracer::clipsBounds(const Vec3d& from, const Vec3d& to) const {
  double t0, t1;
  return bounds_.clip(Ray<double>{from, to - from}, 0.0, 1.0, t0, t1);
}

bool PairTracer::traceUnculled(const LatticePoint& in, const LatticePoint& out, RasterHit& hit, bool& traced) const {
  traced = false;
  const Vec3d from = in.toVec(), to = out.toVec();
  if (!clipsBounds(from, to)) return false;
  traced = true;
  hit = RasterHit{in, out, 0.0, {}};
  if (!traceClosed(from, to, hit.s, hit.normal)) return false;
  hit.normal = glm::normalize(hit.normal);
  return true;
}

bool PairTracer::traceCandidate(const LatticePoint& in, const LatticePoint& out, const CoverCull::Fan& fan,
                                std::uint64_t pieces, RasterHit& hit, bool& traced) const {
  traced = false;
  const Vec3d from = in.toVec(), to = out.toVec();
  if (parts_.empty()) return cull_.mayTouch(fan, to, pieces) && traceUnculled(in, out, hit, traced);
  std::array<CoverCull::Near, kMaxCoverPieces> near;
  const std::size_t count = cull_.touching(fan, to, pieces, near.data());
  if (count == 0) return false;
  hit = RasterHit{in, out, 0.0, {}};
  // The parts decide where one of them is hit first; a miss, a tie or a start
  // inside a part goes to the whole object, as every segment did before. A
  // segment entering a part crosses the object's box, so only the others
  // are clipped against it (for the count of segments traced).
  if (!nearestPart(from, to, near.data(), count, hit.s, hit.normal)) {
    if (!clipsBounds(from, to)) return false;
    traced = true;
    if (!traceClosed(from, to, hit.s, hit.normal)) return false;
  }
  traced = true;
  hit.normal = glm::normalize(hit.normal);
  return true;
}

// The union's first enter (render/shapes/union_core.hpp: the earliest enter
// of any child; the first asked on a tie) read from the parts the segment
// passes near: the others cannot be entered (their pieces are clear of it).
// Each part's enter is its own arithmetic whatever else is asked, so where
// one part enters first the answer is the union's to the bit. A part asked
// up to just past the best enter so far reveals a tie, whose winner depends
// on the union's order: then, as for a miss or a start inside, false.
bool PairTracer::nearestPart(const Vec3d& from, const Vec3d& to, CoverCull::Near* near, std::size_t count, double& s,
                             Vec3d& normal) const {
  // Nearest first, so the parts behind the first one entered are mostly
  // turned away by their own box test against the shorter limit.
  for (std::size_t i = 1; i < count; ++i)
    for (std::size_t j = i; j > 0 && near[j].along < near[j - 1].along; --j) std::swap(near[j], near[j - 1]);
  const Ray<double> ray = Ray<double>{from, to - from}.transformed(latticeToObject_);
  Hit<double> best, part;
  bool found = false, inside = false;
  for (std::size_t i = 0; i < count; ++i) {
    // The next double above a positive best: ties are entered before it.
    const double limit = found ? std::bit_cast<double>(std::bit_cast<std::uint64_t>(best.t) + 1) : 1.0;
    if (parts_[near[i].piece]->firstEnter(ray, 0.0, limit, part, inside)) {
      if (found && part.t == best.t) return false;
      best = part;
      found = true;
    }
    if (inside) return false;
  }
  if (!found) return false;
  s = best.t;
  normal = best.normal;
  return true;
}

// The segment against the closed object: if it misses, the four segments
// shifted sideways by the graze tolerance decide whether it touches the
// surface (an exactly tangent segment gives a double root that rounding may
// lose either way; a shifted one cuts a clean chord).
bool PairTracer::traceClosed(const Vec3d& from, const Vec3d& to, double& s, Vec3d& normal) const {
  if (traceSegment(object_, latticeToObject_, from, to, s, normal)) return true;
  const Vec3d d = to - from;
  const Vec3d a = std::abs(d.x) <= std::abs(d.y) && std::abs(d.x) <= std::abs(d.z) ? Vec3d(1, 0, 0)
                  : std::abs(d.y) <= std::abs(d.z)                                 ? Vec3d(0, 1, 0)
                                                                                  : Vec3d(0, 0, 1);
  const Vec3d u = glm::normalize(glm::cross(d, a));
  const Vec3d v = glm::normalize(glm::cross(d, u));
  const double e = grazeTolerance_;
  bool found = false;
  for (const Vec3d& offset : {u * e, -u * e, v * e, -v * e}) {
    double sOffset;
    Vec3d nOffset;
    if (traceSegment(object_, latticeToObject_, from + offset, to + offset, sOffset, nOffset) &&
        (!found || sOffset < s)) {
      found = true;
      s = sOffset;
      normal = nOffset;
    }
  }
  return found;
}

namespace {

class Rasterizer {
 public:
  Rasterizer(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
             const ObjectParts* parts, const RasterOptions& options)
      : options_(options),
        box_(box),
        points_(box.boundaryPoints()),
        tracer_(box, object, cover, parts, options.grazeTolerance) {
    faces_.reserve(points_.size());
    for (const LatticePoint& p : points_) faces_.push_back(box.facesOf(p));
    // Face masks have 6 bits: every pair's multiplicity is one of 64 x 64
    // (a look-up instead of three popcounts, which are library calls on x86-64's baseline).
    for (unsigned a = 0; a < 64; ++a)
      for (unsigned b = 0; b < 64; ++b)
        multiplicity_[a * 64 + b] = static_cast<std::uint8_t>(
            LatticeBox::pairMultiplicity(static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b)));
    perPoint_.resize(points_.size());
    // A row's pair counts depend on its point's faces only: eq. 1.3's
    // multiplicities summed over the points of each face mask.
    std::array<std::uint64_t, 64> ofMask{};
    for (const std::uint8_t f : faces_) ++ofMask[f];
    for (unsigned a = 0; a < 64; ++a)
      for (unsigned b = 0; b < 64; ++b) {
        const std::uint8_t m = multiplicity_[a * 64 + b];
        pairsFrom_[a] += ofMask[b] * m;
        distinctFrom_[a] += m != 0 ? ofMask[b] : 0;
      }
    for (unsigned a = 0; a < 64; ++a)
      if (multiplicity_[a * 64 + a] != 0 && ofMask[a] != 0) --distinctFrom_[a];  // the point and itself
  }

  RasterResult run() {
    const auto start = std::chrono::steady_clock::now();
    const unsigned threads = rasterWorkers(options_.threads, points_.size());
    Progress progress("rasterize", points_.size(), "points");
    if (!options_.progress) progress.setEnabled(false);

    std::vector<RasterStats> stats(threads);
    const auto work = [this, &stats, &progress](unsigned w) {
      // A worker's counts and fan are its own locals, the counts stored at the
      // end: neighbouring slots of shared arrays would share cache lines,
      // and every pair's count would move the line between the cores.
      RasterStats counted;
      CoverCull::Fan fan;
      ExitCandidates exits(box_, points_);
      std::vector<ExitCandidates::Candidate> candidates;
      std::vector<RasterHit> hits;
      for (std::size_t i = next_.fetch_add(1); i < points_.size(); i = next_.fetch_add(1)) {
        tracePoint(i, counted, fan, exits, candidates, hits);
        progress.advance();
      }
      stats[w] = counted;
    };
    // runWorkers keeps worker 0 in the caller's thread (no allocator arena of
    // its own) and carries the first exception (std::bad_alloc) to the caller.
    runWorkers(threads, work, [this] { next_.store(points_.size()); });
    progress.finish();

    RasterResult result;
    for (const RasterStats& s : stats) {
      result.stats.pairs += s.pairs;
      result.stats.hits += s.hits;
      result.stats.distinctPairs += s.distinctPairs;
      result.stats.traced += s.traced;
    }
    // The lists stay as made (each sized exactly): joining them would hold
    // every hit twice (lht/raster/raster_hits.hpp).
    result.hits = RasterHits(std::move(perPoint_));
    result.stats.buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

 private:
  void tracePoint(std::size_t i, RasterStats& stats, CoverCull::Fan& fan, ExitCandidates& exits,
                  std::vector<ExitCandidates::Candidate>& candidates, std::vector<RasterHit>& scratch) {
    const LatticePoint& in = points_[i];
    const std::uint8_t facesIn = faces_[i];
    // Every pair of the row is counted by its faces; only the candidates are visited.
    stats.pairs += pairsFrom_[facesIn];
    stats.distinctPairs += distinctFrom_[facesIn];
    // Grown in the worker's list, stored once: perPoint_'s neighbouring headers share cache lines.
    std::vector<RasterHit>& out = scratch;
    out.clear();
    const CoverCull& cull = tracer_.cull();
    // pieces: a candidate's (lht/raster/exit_candidates.hpp); without a cull every pair is traced.
    const auto visit = [&](std::size_t j, bool candidate, std::uint64_t pieces) {
      RasterHit hit;
      bool traced = false;
      const bool hits = candidate ? tracer_.traceCandidate(in, points_[j], fan, pieces, hit, traced)
                                  : tracer_.traceUnculled(in, points_[j], hit, traced);
      if (traced) ++stats.traced;
      if (hits) {
        stats.hits += multiplicity_[facesIn * 64u + faces_[j]];
        out.push_back(hit);
      }
    };
    if (cull.active()) {
      cull.aim(in.toVec(), facesIn, fan);
      exits.collect(cull, fan, facesIn, candidates);
      for (const ExitCandidates::Candidate& c : candidates)
        if (!(facesIn & faces_[c.point])) visit(c.point, true, c.pieces);
    } else {
      for (std::size_t j = 0; j < points_.size(); ++j)
        if (!(facesIn & faces_[j])) visit(j, false, 0);
    }
    // Copied at its size: the worker's list keeps its room for the next row.
    const std::size_t kept = out.size();
    perPoint_[i].assign(out.begin(), out.end());
    const std::uint64_t held = held_.fetch_add(kept) + kept;
    const std::uint64_t done = done_.fetch_add(1) + 1;
    if (held > options_.maxHits) throw RasterHitLimit(held, done, points_.size());
  }

  RasterOptions options_;
  const LatticeBox& box_;
  std::vector<LatticePoint> points_;
  PairTracer tracer_;
  std::vector<std::uint8_t> faces_;
  std::array<std::uint8_t, 64 * 64> multiplicity_{};  // by (faces of p_i) * 64 + faces of p_o
  std::array<std::uint64_t, 64> pairsFrom_{};     // eq. 1.3's pairs of a row, by the faces of its p_i
  std::array<std::uint64_t, 64> distinctFrom_{};  // its distinct pairs (p_i != p_o, multiplicity > 0)
  std::vector<std::vector<RasterHit>> perPoint_;
  std::atomic<std::size_t> next_{0};
  std::atomic<std::uint64_t> held_{0};  // hits so far, all threads (the running count)
  std::atomic<std::uint64_t> done_{0};  // rows traced
};

}  // namespace

unsigned rasterWorkers(unsigned threads, std::size_t points) {
  return std::max(1u, std::min<unsigned>(threads ? threads : hardwareThreads(),
                                         static_cast<unsigned>(std::max<std::size_t>(1, points))));
}

RasterResult rasterize(const LatticeBox& box, const Primitive<double>& object, const RasterOptions& options) {
  return rasterize(box, object, nullptr, options);
}

RasterResult rasterize(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
                       const RasterOptions& options) {
  return rasterize(box, object, cover, nullptr, options);
}

RasterResult rasterize(const LatticeBox& box, const Primitive<double>& object, const ObjectCover* cover,
                       const ObjectParts* parts, const RasterOptions& options) {
  Rasterizer rasterizer(box, object, cover, parts, options);
  return rasterizer.run();
}

RasterResult rasterize(const LatticeBox& box, const LatticeObject& object, const RasterOptions& options) {
  return rasterize(box, *object.primitive, object.cover ? &*object.cover : nullptr,
                   object.parts ? &*object.parts : nullptr, options);
}

}  // namespace lattice::lht
