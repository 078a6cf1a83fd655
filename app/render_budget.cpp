#include "app/render_budget.hpp"

#include <fmt/format.h>
#include <malloc.h>

#include "foundation/error.hpp"

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

}  // namespace

void shareOneAllocatorArena() {
#ifdef M_ARENA_MAX
  ::mallopt(M_ARENA_MAX, 1);
#endif
}

MemoryPlanRequest renderBudgetRequest(std::uint64_t budget, int width, int height, const quantize::PipelineOptions& pipeline,
                                      bool modeChosenByUser, const devices::Device* device, bool writesPng) {
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
  // libpng's zlib deflate state (two 128 KiB windows at the default levels)
  // and its row buffers: measured 200-310 KiB beyond the picture itself;
  // 384 KiB left fuzzy-sphere-1000's truecolour render 20 KiB above its
  // prediction on 2026-12-02 (bench/memory-calibration.sh), hence 448.
  if (writesPng) request.deviceItems.push_back({"PNG encoder", 448 * 1024});
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
