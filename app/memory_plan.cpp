#include "app/memory_plan.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "lht/table/compressed_table.hpp"
#include "lht/table/entry_codec.hpp"
#include "lht/table/hash_table.hpp"
#include "foundation/error.hpp"
#include "foundation/system/resident_memory.hpp"

namespace lattice::app {

const char* staticBuildAdvice() {
  // Advice that only helps a dynamically linked build (cmake/LatticeDependencies.cmake).
#ifdef LATTICE_STATIC_BUILD
  return "";
#else
  return ", or use the static build (-DLATTICE_STATIC=ON), whose code is about 1.5 MiB smaller resident";
#endif
}

namespace {

std::uint64_t total(const std::vector<MemoryItem>& items) {
  std::uint64_t sum = 0;
  for (const MemoryItem& item : items) sum += item.bytes;
  return sum;
}

std::string listItems(const std::vector<MemoryItem>& items) {
  std::string out;
  for (const MemoryItem& item : items) {
    if (item.bytes == 0) continue;
    out += fmt::format("{}{} {}", out.empty() ? "" : " + ", formatBytes(item.bytes), item.what);
  }
  return out;
}

// One arrangement of the output side: a pipeline mode and a histogram form.
struct Arrangement {
  quantize::PipelineMode mode;
  quantize::HistogramForm histogram;
};

MemoryPlan costOf(const MemoryPlanRequest& request, Arrangement arrangement) {
  MemoryPlan plan;
  plan.mode = arrangement.mode;
  plan.histogram = arrangement.histogram;
  plan.quantized = request.quantized;
  plan.items.push_back({"resident after building the scene", request.resident});
  if (request.quantized) {
    quantize::PipelineOptions options = request.pipeline;
    options.mode = arrangement.mode;
    options.quantize.histogram = arrangement.histogram;
    const quantize::PipelineReport buffers = quantize::pipelineBuffers(request.width, request.height, options);
    plan.items.push_back({"histogram", buffers.histogramBytes});
    plan.items.push_back({"rows", buffers.rowBytes + buffers.errorRowBytes});
    plan.items.push_back({"frame buffer", buffers.frameBytes});
  }
  for (const MemoryItem& item : request.deviceItems) plan.items.push_back(item);
  plan.items.push_back({"code and buffers not yet touched", kUntouchedAllowance});
  // The scene's build may already have peaked higher (a rasterizer's
  // temporaries): the high-water mark cannot come down.
  plan.predictedPeak = std::max(total(plan.items), request.peakSoFar);
  return plan;
}

// Fastest first: a mode's full histogram before its small one, and the frame
// mode before the two-pass mode; what the user chose stays as chosen.
std::vector<Arrangement> candidateArrangements(const MemoryPlanRequest& request) {
  const quantize::HistogramForm asked = request.pipeline.quantize.histogram;
  if (!request.quantized) return {{request.pipeline.mode, asked}};
  std::vector<quantize::PipelineMode> modes{quantize::PipelineMode::Frame, quantize::PipelineMode::TwoPass};
  if (request.modeChosenByUser) modes = {request.pipeline.mode};
  std::vector<quantize::HistogramForm> forms{quantize::HistogramForm::Full, quantize::HistogramForm::Small};
  if (request.histogramChosenByUser) forms = {asked};
  std::vector<Arrangement> out;
  for (quantize::PipelineMode mode : modes)
    for (quantize::HistogramForm form : forms) out.push_back({mode, form});
  return out;
}

}  // namespace

std::string MemoryPlan::summary() const {
  if (!quantized) return fmt::format("predicted peak {} ({})", formatBytes(predictedPeak), listItems(items));
  return fmt::format("{} mode, {} histogram, predicted peak {} ({})", pipelineModeName(mode),
                     histogram == quantize::HistogramForm::Small ? "small" : "full", formatBytes(predictedPeak),
                     listItems(items));
}

std::uint64_t leastOutputBytes(const MemoryPlanRequest& request) {
  MemoryPlanRequest outputOnly = request;
  outputOnly.resident = 0;
  outputOnly.peakSoFar = 0;
  std::uint64_t least = UINT64_MAX;
  for (const Arrangement& a : candidateArrangements(request)) least = std::min(least, costOf(outputOnly, a).predictedPeak);
  return least;
}

MemoryPlan planMemory(const MemoryPlanRequest& request) {
  const std::string budget = formatBytes(request.budget);
  if (request.peakSoFar > request.budget)
    throw Error(ErrorKind::Budget,
                fmt::format("--memory-budget {}: building the scene alone peaked at {} resident ({} now); no "
                            "output mode can undo that. Raise the budget, rasterize lattices beforehand and name "
                            "the .lht in the scene's `cache =` key{} (docs/memory.md)",
                            budget, formatBytes(request.peakSoFar), formatBytes(request.resident), staticBuildAdvice()));
  std::vector<MemoryPlan> tried;
  for (const Arrangement& a : candidateArrangements(request)) {
    MemoryPlan plan = costOf(request, a);
    if (plan.predictedPeak <= request.budget) return plan;
    tried.push_back(std::move(plan));
  }
  const MemoryPlan& smallest = *std::min_element(
      tried.begin(), tried.end(), [](const MemoryPlan& a, const MemoryPlan& b) { return a.predictedPeak < b.predictedPeak; });
  std::string advice;
  if (request.modeChosenByUser && request.pipeline.mode != quantize::PipelineMode::TwoPass) {
    MemoryPlanRequest twoPass = request;
    twoPass.pipeline.mode = quantize::PipelineMode::TwoPass;
    const MemoryPlan other = costOf(twoPass, {quantize::PipelineMode::TwoPass, request.histogramChosenByUser
                                                                                  ? request.pipeline.quantize.histogram
                                                                                  : quantize::HistogramForm::Small});
    if (other.predictedPeak <= request.budget) advice = " --mode passes would fit; drop --mode or choose it.";
  }
  if (advice.empty())
    advice = fmt::format(" It needs at least {}: raise the budget or render a smaller picture{} (docs/memory.md).",
                         formatBytes(smallest.predictedPeak), staticBuildAdvice());
  throw Error(ErrorKind::Budget, fmt::format("--memory-budget {} cannot be met: {}.{}", budget, smallest.summary(),
                                             advice));
}

TablePacking chooseTablePacking(std::uint64_t budget, std::uint64_t resident, std::uint64_t hitListBytes,
                                std::uint64_t leastOutput, std::uint64_t entries, lht::LhtPrecision requested) {
  const auto fits = [&](lht::LhtPrecision form) {
    const std::uint64_t table = lht::LatticeHashTable::expectedMemory(entries, form);
    const std::uint64_t later = (resident > hitListBytes ? resident - hitListBytes : 0) + table + leastOutput;
    return resident + table <= budget && later <= budget;
  };
  const auto packing = [&](lht::LhtPrecision form) {
    return TablePacking{form, lht::LatticeHashTable::expectedMemory(entries, form)};
  };
  if (fits(requested)) return packing(requested);
  // The forms no larger than the one asked for, smallest first.
  std::vector<lht::LhtPrecisionInfo> smaller;
  for (const lht::LhtPrecisionInfo& info : lht::kLhtPrecisions)
    if (info.entryBytes < lht::entryBytes(requested)) smaller.push_back(info);
  std::sort(smaller.begin(), smaller.end(), [](const auto& a, const auto& b) { return a.entryBytes < b.entryBytes; });
  for (const lht::LhtPrecisionInfo& info : smaller)
    if (fits(info.precision)) return packing(info.precision);
  return packing(requested);
}

std::uint64_t expectedTableBytes(lht::LhtForm form, lht::LhtPrecision precision, std::uint64_t entries,
                                 const std::array<int, 3>& cells) {
  if (form != lht::LhtForm::Compressed) return lht::LatticeHashTable::expectedMemory(entries, precision);
  const std::uint64_t words = (lht::CompressedTable::bitmapBits(cells, lht::PairLayout::Symmetric) + 63) / 64;
  const std::uint64_t ranks = (words + lht::CompressedTable::kBlockWords - 1) / lht::CompressedTable::kBlockWords;
  constexpr std::uint64_t kBuildPairBytes = sizeof(std::pair<std::uint64_t, std::uint32_t>);
  return words * 8 + ranks * 4 + entries * (lht::payloadBytes(precision) + kBuildPairBytes);
}

RasterAdmission admitRaster(std::uint64_t budget, std::uint64_t resident, std::uint64_t leastOutput,
                            const lht::RasterEstimate& estimate,
                            const std::function<std::uint64_t(std::uint64_t entries)>& tableBytes) {
  const auto needWith = [&](std::uint64_t hits) {
    const std::uint64_t table = tableBytes(hits);
    return resident + table + std::max(estimate.bytesFor(hits), leastOutput);
  };
  RasterAdmission a;
  a.tableBytes = tableBytes(estimate.hits);
  a.need = needWith(estimate.hits);
  a.fits = a.need <= budget;
  // The need grows with the hits: the last count that fits, by bisection
  // (no more hits than distinct pairs can come).
  std::uint64_t lo = 0, hi = estimate.distinctPairs;
  if (needWith(lo) > budget) return a;
  while (lo < hi) {
    const std::uint64_t mid = lo + (hi - lo + 1) / 2;
    if (needWith(mid) <= budget)
      lo = mid;
    else
      hi = mid - 1;
  }
  a.maxHits = lo;
  return a;
}

}  // namespace lattice::app
