#pragma once
// The --memory-budget side of `lattice render` (docs/memory.md): what the
// command tells the planner about its outputs, the lattice packing hook the
// scene's tables are built with, the plan made after, and the check of the
// measured peak at the end. The policy itself is app/memory_plan.hpp.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/memory_plan.hpp"
#include "app/render_events.hpp"
#include "devices/device.hpp"
#include "loader/lattice_definition.hpp"
#include "foundation/system/resident_memory.hpp"

namespace lattice::app {

// The budget of a render given no --memory-budget: a fraction of the
// machine's physical memory; nullopt where that is unknown (no budget).
std::optional<std::uint64_t> defaultMemoryBudget();

// What the lattices rasterized in one render may take.
struct RasterRoom {
  std::uint64_t budget = 0;
  bool chosen = false;            // --memory-budget given; else the default (which never repacks)
  std::uint64_t leastOutput = 0;  // the output side's least (leastOutputBytes), once the picture's size is known
  std::string name() const;       // how messages name the budget
};

// The admission of every lattice rasterized in the render (docs/memory.md):
// before any work, its estimated need (admitRaster) against `room`; a
// lattice that cannot fit is refused with lattice::Error(Input), naming the
// figures and the ways out (the on-demand form, a larger spacing, a larger
// budget); one that can is rasterized with the running count's limit. When
// what is resident already breaks the budget: lattice::Error(Budget). The
// estimate's sample is traced only when the worst case (every distinct pair
// a hit) does not fit.
lht::RasterAdmissionHook rasterizingWithin(std::shared_ptr<const RasterRoom> room);

// Before any thread starts, under a budget: every thread allocates from the
// one main allocator arena. A worker thread's own arena (glibc makes one per
// thread) keeps what it freed resident; on Plate 6 the rasterizer's second
// thread left 0.15-0.3 MiB there (docs/memory.md). Contention on the one
// arena costs little: the render loops do not allocate.
void shareOneAllocatorArena();

// The request for a width x height picture, before anything is measured.
// `device` is the device table's entry (its driver's and emulator's memory),
// or nullptr for a truecolour picture; `pngWorkers`: the threads a saved
// picture (-o) is deflated on, 0 when none is saved.
MemoryPlanRequest renderBudgetRequest(std::uint64_t budget, int width, int height, const quantize::PipelineOptions& pipeline,
                                      bool modeChosenByUser, const devices::Device* device, unsigned pngWorkers);

// The packing of lattices rasterized in this run: the form the budget can
// hold, decided when their entry count is known (chooseTablePacking); a
// lattice packed otherwise than asked is a TableRepacked event.
lht::TablePackingHook tablePackingWithin(const MemoryPlanRequest& request, RenderEvents events = {});

// Once the scene is built: returns freed allocator pages to the system,
// measures, plans (lattice::Error(Budget) when nothing fits); the plan is a
// MemoryPlanned event.
MemoryPlan planBuiltRender(MemoryPlanRequest request, const RenderEvents& events = {});

// After the render: the measured peak is a PeakMeasured event;
// lattice::Error(Budget) if it broke the budget (the outputs are written by then).
void checkPeakAgainst(std::uint64_t budget, const RenderEvents& events = {});

}  // namespace lattice::app
