#include "quantize/median_cut.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "foundation/error.hpp"

namespace lattice::quantize {
namespace {

// Channel order used for axes: 0 = red, 1 = green, 2 = blue (6-bit values).
unsigned channel6(Color18 c, int axis) { return axis == 0 ? red6(c) : axis == 1 ? green6(c) : blue6(c); }

struct Box {
  std::array<int, 3> lo{0, 0, 0};
  std::array<int, 3> hi{63, 63, 63};
  std::uint64_t population = 0;
  std::size_t distinct = 0;
  double squaredError = 0;  // sum over pixels of |colour - box mean|^2, 6-bit units
  std::array<double, 3> mean{0, 0, 0};
};

// Shrink-to-fit: the smallest box around the non-empty cells, with the
// statistics the split choice and the representative need.
void shrink(Box& box, const Histogram& histogram) {
  std::array<int, 3> lo{64, 64, 64}, hi{-1, -1, -1};
  std::array<double, 3> sum{0, 0, 0};
  double sumSquares = 0;
  std::uint64_t population = 0;
  std::size_t distinct = 0;
  histogram.forEachInBox(box.lo.data(), box.hi.data(), [&](Color18 c, std::uint32_t n) {
    ++distinct;
    population += n;
    for (int a = 0; a < 3; ++a) {
      int v = int(channel6(c, a));
      lo[a] = std::min(lo[a], v);
      hi[a] = std::max(hi[a], v);
      sum[a] += double(n) * v;
      sumSquares += double(n) * v * v;
    }
  });
  box.population = population;
  box.distinct = distinct;
  if (population == 0) return;
  box.lo = lo;
  box.hi = hi;
  double meanSquares = 0;
  for (int a = 0; a < 3; ++a) {
    box.mean[a] = sum[a] / double(population);
    meanSquares += box.mean[a] * sum[a];
  }
  box.squaredError = std::max(0.0, sumSquares - meanSquares);
}

// Longest side in 6-bit units; ties go green, red, blue (green carries most of
// the luminance, so it is the better tie-breaker for the eye).
int longestAxis(const Box& box) {
  constexpr std::array<int, 3> order{1, 0, 2};
  int best = order[0];
  for (int a : order)
    if (box.hi[a] - box.lo[a] > box.hi[best] - box.lo[best]) best = a;
  return best;
}

// Pixel counts of the box projected on one axis.
std::array<std::uint64_t, 64> project(const Box& box, int axis, const Histogram& histogram) {
  std::array<std::uint64_t, 64> counts{};
  histogram.forEachInBox(box.lo.data(), box.hi.data(),
                         [&](Color18 c, std::uint32_t n) { counts[channel6(c, axis)] += n; });
  return counts;
}

// Last plane of the lower half; always in [lo, hi-1] so both halves keep a
// non-empty boundary plane.
int medianCutPlane(const Box& box, int axis, const std::array<std::uint64_t, 64>& counts) {
  std::uint64_t lower = 0;
  for (int s = box.lo[axis]; s < box.hi[axis]; ++s) {
    lower += counts[s];
    if (2 * lower >= box.population) return s;
  }
  return box.hi[axis] - 1;
}

int varianceCutPlane(const Box& box, int axis, const std::array<std::uint64_t, 64>& counts) {
  double totalN = 0, totalS = 0, totalQ = 0;
  for (int v = box.lo[axis]; v <= box.hi[axis]; ++v) {
    double n = double(counts[v]);
    totalN += n;
    totalS += n * v;
    totalQ += n * v * v;
  }
  double n = 0, s = 0, q = 0;
  double bestError = INFINITY;
  int best = box.lo[axis];
  for (int plane = box.lo[axis]; plane < box.hi[axis]; ++plane) {
    double c = double(counts[plane]);
    n += c;
    s += c * plane;
    q += c * plane * plane;
    double rn = totalN - n, rs = totalS - s, rq = totalQ - q;
    double error = (n > 0 ? q - s * s / n : 0) + (rn > 0 ? rq - rs * rs / rn : 0);
    if (error < bestError) {
      bestError = error;
      best = plane;
    }
  }
  return best;
}

Rgb8 representative(const Box& box, const Histogram& histogram) {
  std::array<double, 3> sum{0, 0, 0};
  histogram.forEachInBox(box.lo.data(), box.hi.data(), [&](Color18 c, std::uint32_t n) {
    for (int a = 0; a < 3; ++a) sum[a] += double(n) * expand6to8(channel6(c, a));
  });
  auto channel = [&](int a) { return static_cast<std::uint8_t>(std::lround(sum[a] / double(box.population))); };
  return Rgb8{channel(0), channel(1), channel(2)};
}

void checkArguments(int maxColors, const QuantizeOptions& options) {
  if (maxColors < 1 || maxColors > 256)
    throw Error(ErrorKind::Usage, fmt::format("--colors {} is out of range: give 1 to 256", maxColors));
  if (options.refineIterations < 0 || options.refineIterations > 100)
    throw Error(ErrorKind::Usage,
                fmt::format("--refine {} is out of range: give 0 to 100 iterations", options.refineIterations));
}

}  // namespace

Palette medianCut(const Histogram& histogram, int maxColors, const QuantizeOptions& options) {
  checkArguments(maxColors, options);
  if (histogram.form() == HistogramForm::Full && histogram.cells().size() != Histogram::kCells)
    throw Error(ErrorKind::Internal, "median cut: histogram storage was released");
  std::vector<Box> boxes(1);
  boxes.reserve(static_cast<std::size_t>(maxColors));  // no doubling: 18 KiB at 256, not 27 (the firmware's RAM)
  shrink(boxes[0], histogram);
  if (boxes[0].population == 0) return {};

  while (boxes.size() < static_cast<std::size_t>(maxColors)) {
    // The box to split: among those with two or more colours, the most
    // populous (median) or the one with the most squared error (variance).
    // Strict comparison keeps the earliest box on ties: deterministic.
    Box* target = nullptr;
    for (Box& box : boxes) {
      if (box.distinct < 2) continue;
      bool better = target == nullptr ||
                    (options.split == SplitRule::Median ? box.population > target->population
                                                        : box.squaredError > target->squaredError);
      if (better) target = &box;
    }
    if (target == nullptr) break;  // every box is a single colour

    int axis = longestAxis(*target);
    auto counts = project(*target, axis, histogram);
    int plane = options.split == SplitRule::Median ? medianCutPlane(*target, axis, counts)
                                                   : varianceCutPlane(*target, axis, counts);
    Box upper = *target;
    target->hi[axis] = plane;
    upper.lo[axis] = plane + 1;
    shrink(*target, histogram);
    shrink(upper, histogram);
    boxes.push_back(upper);  // invalidates target; not used again this round
  }

  Palette palette;
  palette.reserve(boxes.size());
  for (const Box& box : boxes) palette.push_back(representative(box, histogram));
  if (options.refineIterations > 0) refinePalette(histogram, palette, options.refineIterations);
  return palette;
}

void refinePalette(const Histogram& histogram, Palette& palette, int iterations) {
  if ((histogram.form() == HistogramForm::Full && histogram.cells().size() != Histogram::kCells) || palette.empty())
    return;
  struct Accumulator {
    double n = 0, r = 0, g = 0, b = 0;
  };
  std::vector<Accumulator> sums(palette.size());
  for (int iteration = 0; iteration < iterations; ++iteration) {
    std::fill(sums.begin(), sums.end(), Accumulator{});
    histogram.forEach([&](Color18 c, std::uint32_t n) {
      int r = expand6to8(red6(c)), g = expand6to8(green6(c)), b = expand6to8(blue6(c));
      Accumulator& acc = sums[nearestEntry(r, g, b, palette)];
      acc.n += n;
      acc.r += double(n) * r;
      acc.g += double(n) * g;
      acc.b += double(n) * b;
    });
    bool moved = false;
    for (std::size_t i = 0; i < palette.size(); ++i) {
      if (sums[i].n == 0) continue;  // an entry nothing is nearest to keeps its colour
      auto mean = [&](double s) { return static_cast<std::uint8_t>(std::lround(s / sums[i].n)); };
      Rgb8 next{mean(sums[i].r), mean(sums[i].g), mean(sums[i].b)};
      if (!(next == palette[i])) moved = true;
      palette[i] = next;
    }
    if (!moved) break;
  }
}

}  // namespace lattice::quantize
