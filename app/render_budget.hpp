#pragma once
// The --memory-budget side of `lattice render` (docs/memory.md): what the
// command tells the planner about its outputs, the lattice packing hook the
// scene's tables are built with, the plan made after, and the check of the
// measured peak at the end. The policy itself is app/memory_plan.hpp.
#include <cstdint>
#include <string>
#include <vector>

#include "app/memory_plan.hpp"
#include "lht/lattice_definition.hpp"
#include "foundation/resident_memory.hpp"

namespace lattice::app {

// Where the render's picture goes, as far as memory is concerned.
struct RenderOutputs {
  std::string device;     // png, apollo, tek4125, tek4027
  bool writesPng = false;  // -o
  int deviceWidth = 0;     // the device's screen (Apollo, the Tek emulator)
  int deviceHeight = 0;
};

// The request for a width x height picture, before anything is measured.
MemoryPlanRequest renderBudgetRequest(std::uint64_t budget, int width, int height, const PipelineOptions& pipeline,
                                      bool modeChosenByUser, const RenderOutputs& outputs);

// The packing of lattices rasterized in this run: the form the budget can
// hold, decided when their entry count is known (chooseTablePacking).
lht::TablePackingHook tablePackingWithin(const MemoryPlanRequest& request);

// Once the scene is built: returns freed allocator pages to the system,
// measures, plans (lattice::Error(Budget) when nothing fits) and logs the plan.
MemoryPlan planBuiltRender(MemoryPlanRequest request);

// After the render: logs the measured peak; lattice::Error(Budget) if it
// broke the budget (the outputs are written by then).
void checkPeakAgainst(std::uint64_t budget);

}  // namespace lattice::app
