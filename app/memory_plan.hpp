#pragma once
// --memory-budget (docs/memory.md): choosing how a render holds its data so
// that the process's peak resident memory stays within a budget, or saying
// why no choice can.
//
// The plan is made once the scene is built, from what the process measures
// resident then (code faulted in so far, the scene, its lattice tables and
// BVH) plus what the rest of the render will add: the quantizer's buffers for
// each pipeline mode (pipelineBuffers), the device's own images, and an
// allowance for code and transport buffers not yet touched.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lht/raster/raster_estimate.hpp"
#include "lht/table/lht_form.hpp"
#include "lht/table/lht_precision.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {

// Code of the quantizer, driver and PNG writer that is not resident yet when
// the plan is made, the 64 KiB stream-file buffer and allocator slack. Set so
// that the predicted peak was at or above the measured one over the example
// scenes x every output device x both builds (docs/memory.md, "Calibration").
inline constexpr std::uint64_t kUntouchedAllowance = 512 * 1024;

struct MemoryItem {
  std::string what;
  std::uint64_t bytes = 0;
};

struct MemoryPlanRequest {
  std::uint64_t budget = 0;
  std::uint64_t resident = 0;          // measured when planning
  std::uint64_t peakSoFar = 0;         // the high-water mark when planning
  int width = 0, height = 0;
  bool quantized = true;               // false: --device png, no pipeline
  quantize::PipelineOptions pipeline;            // dither, the user's mode
  bool modeChosenByUser = false;       // --mode given: check it, do not change it
  bool histogramChosenByUser = false;  // --histogram given: likewise
  std::vector<MemoryItem> deviceItems; // images the output device will hold
};

struct MemoryPlan {
  quantize::PipelineMode mode = quantize::PipelineMode::TwoPass;
  quantize::HistogramForm histogram = quantize::HistogramForm::Full;
  bool quantized = true;  // false: no pipeline, mode and histogram mean nothing
  std::uint64_t predictedPeak = 0;
  std::vector<MemoryItem> items;  // what predictedPeak adds up
  std::string summary() const;    // one line for the log
};

// The fastest arrangement that fits: the frame mode (one render) before the
// two-pass mode (two renders, no frame buffer), each with the full histogram
// before the small one (1 MiB against 64 KiB; the same palette, but at most
// 6144 colours: a picture with more then fails naming the way out); the
// sample mode only when the user asked for it (it changes the palette). lattice::Error(Budget) when
// nothing fits, naming what takes the memory and what to change.
MemoryPlan planMemory(const MemoryPlanRequest& request);

// ", or use the static build (...)" in a dynamically linked build, "" in the
// static one: the end of a refusal's advice.
const char* staticBuildAdvice();

// What the output side will add at the least (the least-memory mode the
// request allows, the device's images, the allowance), whatever is resident:
// the room a lattice table must leave when it is packed before the plan.
std::uint64_t leastOutputBytes(const MemoryPlanRequest& request);

// The LHT form for a freshly rasterized table of `entries` entries, chosen
// while its hit list (hitListBytes) is still resident: `requested` if the
// process can hold it both now (resident + table) and later (the hit list
// freed, plus leastOutput), else the smallest form that can, else
// `requested` (planMemory then refuses with the whole picture). Never a form
// larger than `requested`.
struct TablePacking {
  lht::LhtPrecision form = lht::LhtPrecision::Thesis;
  std::uint64_t tableBytes = 0;  // expected, in that form
};
TablePacking chooseTablePacking(std::uint64_t budget, std::uint64_t resident, std::uint64_t hitListBytes,
                                std::uint64_t leastOutput, std::uint64_t entries, lht::LhtPrecision requested);

// The bytes a rasterized table of `entries` entries holds while it is built
// from the hits: the hashed form's slots; the compressed form's bitmap, rank
// directory and payloads, and its build's pair list (16 B an entry).
// lattice::Error(Input) for a compressed pair space beyond kMaxBitmapBits.
std::uint64_t expectedTableBytes(lht::LhtForm form, lht::LhtPrecision precision, std::uint64_t entries,
                                 const std::array<int, 3>& cells);

// A lattice about to be rasterized, with `resident` bytes resident now. With
// n hits the process holds resident + the rasterizer's bytes for n hits +
// the table of n entries while the table is packed, then resident + the
// table + leastOutput once the hits are freed and the output side exists;
// its need is the larger. `tableBytes(n)`: the table's bytes for n entries.
struct RasterAdmission {
  std::uint64_t need = 0;        // with the estimate's hits
  std::uint64_t tableBytes = 0;  // the table with them
  std::uint64_t maxHits = 0;     // the most hits whose need fits the budget (the running count's limit)
  bool fits = false;             // need <= budget
};
RasterAdmission admitRaster(std::uint64_t budget, std::uint64_t resident, std::uint64_t leastOutput,
                            const lht::RasterEstimate& estimate,
                            const std::function<std::uint64_t(std::uint64_t entries)>& tableBytes);

}  // namespace lattice::app
