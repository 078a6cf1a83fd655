#include "app/render_budget.hpp"

#include <fmt/format.h>
#include <malloc.h>

#include <algorithm>
#include <cmath>

#include "foundation/error.hpp"
#include "io/png_encoder.hpp"
#include "lht/grid/lattice_box.hpp"
#include "lht/raster/raster_estimate.hpp"
#include "lht/table/entry_codec.hpp"

namespace lattice::app {

namespace {

ResidentMemory measuredResidentMemory() {
  const auto resident = residentMemory();
  if (!resident)
    throw Error(ErrorKind::Budget, "--memory-budget needs /proc/self/status to measure resident memory, and this "
                                   "system has none; render without the budget");
  return *resident;
}

std::uint64_t pixels(int w, int h) { return static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h); }

// x rounded up to two significant digits: a spacing to suggest.
double roundUp2(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
  return std::ceil(x / unit - 1e-9) * unit;
}

// A spacing at which the lattice's own need (`need` now) would be within
// `room`, taking the need as proportional to the pairs (eq. 1.3) of the
// box each spacing gives; nullopt if none is found.
std::optional<double> fittingSpacing(const lht::LatticeDefinition& lattice, const lht::RasterEstimate& estimate,
                                     std::uint64_t need, std::uint64_t room) {
  if (need <= room || room == 0 || estimate.pairs == 0) return std::nullopt;
  const Bounds<double>& bounds = lattice.objectBounds();
  // The pairs grow as the fourth power of the cells a side: start there,
  // then widen by 2 % until the box's own pair count fits.
  double spacing = lattice.lambda * std::pow(double(need) / double(room), 0.25);
  for (int step = 0; step < 200; ++step, spacing *= 1.02) {
    const double suggested = roundUp2(spacing);
    try {
      const lht::LatticeBox box(bounds, suggested, lattice.oversample);
      if (double(need) * double(box.pairCountEq13()) / double(estimate.pairs) <= double(room)) return suggested;
    } catch (const Error&) {
      // Too many cells on an axis at this spacing: a larger one comes next.
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> defaultMemoryBudget() {
  // Half: the rest stays for the system, other programs and the page cache,
  // and a render past physical memory swaps for hours instead of failing.
  if (const auto physical = physicalMemory()) return *physical / 2;
  return std::nullopt;
}

std::string RasterRoom::name() const {
  if (chosen) return fmt::format("--memory-budget {}", formatBytes(budget));
  return fmt::format("the default memory budget of {} (half the physical memory; --memory-budget SIZE sets another)",
                     formatBytes(budget));
}

lht::RasterAdmissionHook rasterizingWithin(std::shared_ptr<const RasterRoom> room) {
  return [room = std::move(room)](const lht::LatticeDefinition& lattice, lht::LazyRasterEstimate& lazy,
                                  lht::LhtForm form, lht::LhtPrecision requested) {
    // Without procfs a chosen budget cannot be kept (as planBuiltRender
    // says); the default one then counts the lattice alone.
    const ResidentMemory now = room->chosen ? measuredResidentMemory() : residentMemory().value_or(ResidentMemory{});
    if (now.peak > room->budget || now.current + room->leastOutput > room->budget)
      throw Error(ErrorKind::Budget,
                  fmt::format("{}: before this lattice is rasterized the process holds {} resident (it peaked at "
                              "{}) and the picture needs at least {} more; raise the budget{} (docs/memory.md)",
                              room->name(), formatBytes(now.current), formatBytes(now.peak),
                              formatBytes(room->leastOutput), staticBuildAdvice()));
    // A chosen budget may pack the table in a smaller entry form
    // (tablePackingWithin): the smallest is what must fit.
    std::vector<lht::LhtPrecision> precisions{requested};
    if (room->chosen)
      for (const lht::LhtPrecisionInfo& info : lht::kLhtPrecisions)
        if (info.entryBytes < lht::entryBytes(requested)) precisions.push_back(info.precision);
    const auto tableBytes = [&](std::uint64_t entries) {
      std::uint64_t least = UINT64_MAX;
      for (const lht::LhtPrecision p : precisions)
        least = std::min(least, expectedTableBytes(form, p, entries, lazy.worstCase().cells));
      return least;
    };
    // Every distinct pair a hit within the budget: no sample can refuse the
    // lattice or lower its count below what the rasterizer can reach, so
    // none is traced.
    const RasterAdmission bound = admitRaster(room->budget, now.current, room->leastOutput, lazy.worstCase(), tableBytes);
    if (bound.fits)
      return lht::RasterAllowance{bound.maxHits, fmt::format("more than the {} distinct pairs", bound.maxHits)};
    const lht::RasterEstimate& estimate = lazy.sampled();
    const RasterAdmission admission = admitRaster(room->budget, now.current, room->leastOutput, estimate, tableBytes);
    const std::uint64_t base = now.current + room->leastOutput;
    std::string spacing = "a larger spacing";
    if (const auto larger = fittingSpacing(lattice, estimate, admission.need - std::min(admission.need, base),
                                           room->budget - base))
      spacing = fmt::format("a spacing of about {:g} or more (now {:g})", *larger, lattice.lambda);
    const std::string ways = fmt::format(
        "Build its table on demand instead (form = \"on-demand\" in its [[lattices]] entry, or --lht-form on-demand: "
        "only the pairs rays reach are traced), use {}, or raise the budget (docs/memory.md)",
        spacing);
    const auto& c = estimate.cells;
    if (!admission.fits)
      throw Error(ErrorKind::Input,
                  fmt::format("rasterizing it would take about {} at its peak, over {}: its {} x {} x {} cells give "
                              "{} pairs (p_i, p_o) by eq. 1.3, {} distinct, of which about {} hit the object ({} of "
                              "{} sampled), {} B each while rasterizing, and the {} table, {}; {} is resident already. "
                              "{}",
                              formatBytes(admission.need), room->name(), c[0], c[1], c[2], estimate.pairs,
                              estimate.distinctPairs, estimate.hits, estimate.sampledHits, estimate.sampled,
                              lht::RasterEstimate::kHitBytes, lht::lhtFormName(form), formatBytes(admission.tableBytes),
                              formatBytes(now.current), ways));
    return lht::RasterAllowance{
        admission.maxHits,
        fmt::format("more than the {} that {} leaves room for (about {} were expected). {}", admission.maxHits,
                    room->name(), estimate.hits, ways)};
  };
}

void shareOneAllocatorArena() {
#ifdef M_ARENA_MAX
  ::mallopt(M_ARENA_MAX, 1);
#endif
}

MemoryPlanRequest renderBudgetRequest(std::uint64_t budget, int width, int height, const quantize::PipelineOptions& pipeline,
                                      bool modeChosenByUser, const devices::Device* device, unsigned pngWorkers) {
  const bool writesPng = pngWorkers > 0;
  MemoryPlanRequest request;
  request.budget = budget;
  request.width = width;
  request.height = height;
  request.pipeline = pipeline;
  request.modeChosenByUser = modeChosenByUser;
  request.quantized = device != nullptr;
  if (!device) request.deviceItems.push_back({"truecolour picture", 3 * pixels(width, height)});
  if (device) {
    if (const std::uint64_t driver = device->driverMemory(width, height); driver > 0)
      request.deviceItems.push_back({fmt::format("{} driver", device->title), driver});
    if (writesPng) request.deviceItems.push_back({"emulator screen", device->emulatorMemory});
  }
  // One deflate stream's state (two 128 KiB tables at the default memLevel),
  // its row buffers and the deflated bytes: libpng's encoder measured 200-310
  // KiB beyond the picture itself; 384 KiB left fuzzy-sphere-1000's
  // truecolour render 20 KiB above its prediction on 2026-12-02
  // (bench/memory-calibration.sh), hence 448. Ours (io/png_encoder.hpp)
  // holds as much on one worker, and each further worker its own state and
  // rows.
  if (writesPng) {
    const int widest = device ? std::max(width, device->width) : width;  // an emulator saves its whole screen
    request.deviceItems.push_back(
        {"PNG encoder", 448 * 1024 + (pngWorkers - 1) * io::pngEncoderWorkerBytes(widest, device != nullptr)});
  }
  return request;
}

lht::TablePackingHook tablePackingWithin(const MemoryPlanRequest& request, RenderEvents events) {
  return [budget = request.budget, leastOutput = leastOutputBytes(request), events = std::move(events)](
             const lht::LatticeDefinition& lattice, lht::LhtPrecision requested, std::uint64_t entries,
             std::uint64_t hitListBytes) {
    const TablePacking packing =
        chooseTablePacking(budget, measuredResidentMemory().current, hitListBytes, leastOutput, entries, requested);
    if (packing.form != requested)
      raise(events, TableRepacked{lattice.name, requested, packing.form, packing.tableBytes});
    return packing.form;
  };
}

MemoryPlan planBuiltRender(MemoryPlanRequest request, const RenderEvents& events) {
  // The rasterizer's per-point hit lists are many small blocks, freed by now
  // but kept by the allocator: give those pages back before measuring.
  ::malloc_trim(0);
  const ResidentMemory resident = measuredResidentMemory();
  request.resident = resident.current;
  request.peakSoFar = resident.peak;
  MemoryPlan plan = planMemory(request);
  raise(events, MemoryPlanned{plan.summary()});
  return plan;
}

void checkPeakAgainst(std::uint64_t budget, const RenderEvents& events) {
  const auto resident = residentMemory();
  if (!resident) return;
  raise(events, PeakMeasured{resident->peak, budget});
  // The plan is an estimate: say so, loudly, when the measured peak broke it.
  if (resident->peak > budget)
    throw Error(ErrorKind::Budget,
                fmt::format("the render finished and its outputs are written, but its resident memory peaked at {}, "
                            "over the --memory-budget of {}: the plan's estimate was short (please report it with "
                            "the scene)",
                            formatBytes(resident->peak), formatBytes(budget)),
                Outputs::Keep);
}

}  // namespace lattice::app
