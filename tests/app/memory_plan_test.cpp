// The --memory-budget planner: which pipeline mode it picks for a budget, and
// what it says when nothing fits (app/memory_plan.hpp).
#include <catch2/catch.hpp>

#include "app/memory_plan.hpp"
#include "lht/table/hash_table.hpp"
#include "foundation/error.hpp"

using lattice::quantize::PipelineMode;
using lattice::app::kUntouchedAllowance;
using lattice::app::MemoryPlanRequest;
using lattice::app::planMemory;

namespace {

constexpr std::uint64_t MiB = 1024 * 1024;

MemoryPlanRequest request512(std::uint64_t budget) {
  MemoryPlanRequest r;
  r.budget = budget;
  r.resident = 5 * MiB;
  r.peakSoFar = 5 * MiB;
  r.width = 512;
  r.height = 512;
  r.histogramChosenByUser = true;  // the full form, as the mode tests below assume
  return r;
}

// What each mode adds at 512x512 without dithering: the 1 MiB histogram, a
// Color18 row and an index row (5 B a pixel), and a 4 B/pixel frame.
constexpr std::uint64_t kPasses = 5 * MiB + MiB + 512 * 5 + kUntouchedAllowance;
constexpr std::uint64_t kFrame = kPasses + 512 * 512 * 4;
// The small histogram instead of the full one (quantize/histogram.hpp: 64 KiB at most).
constexpr std::uint64_t kSmallSaves = MiB - 64 * 1024;

std::string budgetError(const MemoryPlanRequest& r) {
  try {
    planMemory(r);
  } catch (const lattice::Error& e) {
    CHECK(e.kind() == lattice::ErrorKind::Budget);
    return e.what();
  }
  FAIL("the plan fitted");
  return {};
}

}  // namespace

TEST_CASE("app:memory_plan_prefers_the_frame_when_it_fits") {
  const auto plan = planMemory(request512(kFrame));
  CHECK(plan.mode == PipelineMode::Frame);
  CHECK(plan.predictedPeak == kFrame);
  CHECK_THAT(plan.summary(), Catch::Contains("frame mode") && Catch::Contains("1.00 MiB frame buffer"));
}

TEST_CASE("app:memory_plan_falls_back_to_two_passes") {
  const auto plan = planMemory(request512(kFrame - 1));
  CHECK(plan.mode == PipelineMode::TwoPass);
  CHECK(plan.predictedPeak == kPasses);
  CHECK(planMemory(request512(kPasses)).mode == PipelineMode::TwoPass);
}

TEST_CASE("app:memory_plan_takes_the_small_histogram_when_the_full_one_does_not_fit") {
  auto r = request512(kFrame - 1);
  r.histogramChosenByUser = false;
  auto plan = planMemory(r);  // one render with the small histogram beats two with the full one
  CHECK(plan.mode == PipelineMode::Frame);
  CHECK(plan.histogram == lattice::quantize::HistogramForm::Small);
  CHECK(plan.predictedPeak == kFrame - kSmallSaves);
  CHECK_THAT(plan.summary(), Catch::Contains("small histogram") && Catch::Contains("64.0 KiB histogram"));
  r.budget = kFrame;
  CHECK(planMemory(r).histogram == lattice::quantize::HistogramForm::Full);  // the full one while it fits
  r.budget = kPasses - kSmallSaves;
  plan = planMemory(r);
  CHECK(plan.mode == PipelineMode::TwoPass);
  CHECK(plan.histogram == lattice::quantize::HistogramForm::Small);
  r.budget = kPasses - kSmallSaves - 1;
  CHECK_THAT(budgetError(r), Catch::Contains("passes mode, small histogram"));
}

TEST_CASE("app:memory_plan_refuses_when_nothing_fits") {
  const std::string message = budgetError(request512(kPasses - 1));
  CHECK_THAT(message, Catch::Contains("cannot be met") && Catch::Contains("passes mode") &&
                          Catch::Contains("needs at least"));
}

TEST_CASE("app:memory_plan_counts_what_the_device_holds") {
  auto r = request512(kFrame);
  r.deviceItems.push_back({"emulator screen", 640 * 480 * 3});
  const auto plan = planMemory(r);
  CHECK(plan.mode == PipelineMode::TwoPass);  // the screen pushes the frame out
  CHECK(plan.predictedPeak == kPasses + 640 * 480 * 3);
  CHECK_THAT(plan.summary(), Catch::Contains("emulator screen"));
}

TEST_CASE("app:memory_plan_keeps_the_users_mode") {
  auto r = request512(kFrame - 1);
  r.modeChosenByUser = true;
  r.pipeline.mode = PipelineMode::Frame;
  CHECK_THAT(budgetError(r), Catch::Contains("--mode passes would fit"));
  r.pipeline.mode = PipelineMode::Sample;
  CHECK(planMemory(r).mode == PipelineMode::Sample);
}

TEST_CASE("app:memory_plan_counts_floyd_steinberg_rows") {
  auto r = request512(kPasses);
  r.pipeline.quantize.dither = lattice::quantize::Dither::FloydSteinberg;
  CHECK_THAT(budgetError(r), Catch::Contains("passes mode"));  // the error rows no longer fit
  r.budget = kPasses + (512 + 2) * 3 * sizeof(int);
  CHECK(planMemory(r).mode == PipelineMode::TwoPass);
}

TEST_CASE("app:memory_plan_cannot_undo_a_peak_already_reached") {
  auto r = request512(64 * MiB);
  r.peakSoFar = 65 * MiB;  // e.g. a lattice rasterized in the process
  CHECK_THAT(budgetError(r), Catch::Contains("building the scene alone peaked at 65.00 MiB") &&
                                 Catch::Contains("cache ="));
}

TEST_CASE("app:memory_plan_for_truecolour_has_no_quantizer") {
  auto r = request512(5 * MiB + 3 * 512 * 512 + kUntouchedAllowance);
  r.quantized = false;
  r.deviceItems.push_back({"truecolour picture", 3 * 512 * 512});
  const auto plan = planMemory(r);
  CHECK(plan.predictedPeak == r.budget);
  CHECK_THAT(plan.summary(), !Catch::Contains("histogram"));
}

TEST_CASE("app:memory_plan_packs_a_lattice_table_in_the_form_that_fits") {
  using lattice::app::chooseTablePacking;
  using lattice::lht::LhtPrecision;
  using lattice::lht::LatticeHashTable;
  constexpr std::uint64_t entries = 100000;
  const std::uint64_t thesis = LatticeHashTable::expectedMemory(entries, LhtPrecision::Thesis);
  const std::uint64_t compact = LatticeHashTable::expectedMemory(entries, LhtPrecision::Compact);
  const std::uint64_t wide = LatticeHashTable::expectedMemory(entries, LhtPrecision::Wide);
  REQUIRE(compact < thesis);
  REQUIRE(thesis < wide);
  const std::uint64_t resident = 4 * MiB, hitList = 4 * MiB, output = 2 * MiB;
  // While the hit list is alive: resident + table is the binding sum.
  CHECK(chooseTablePacking(resident + thesis, resident, hitList, output, entries, LhtPrecision::Thesis).form ==
        LhtPrecision::Thesis);
  const auto packed = chooseTablePacking(resident + thesis - 1, resident, hitList, output, entries, LhtPrecision::Thesis);
  CHECK(packed.form == LhtPrecision::Compact);
  CHECK(packed.tableBytes == compact);
  // Too small for any form: the requested one (the plan refuses later).
  CHECK(chooseTablePacking(resident + compact - 1, resident, hitList, output, entries, LhtPrecision::Thesis).form ==
        LhtPrecision::Thesis);
  // Wide asked for and no room: the smallest form that fits, never a larger one.
  CHECK(chooseTablePacking(resident + thesis, resident, hitList, output, entries, LhtPrecision::Wide).form ==
        LhtPrecision::Compact);
  CHECK(chooseTablePacking(UINT64_MAX / 2, resident, hitList, output, entries, LhtPrecision::Compact).form ==
        LhtPrecision::Compact);
  // After the hit list is freed the output must still fit beside the table.
  const std::uint64_t smallHitList = 1024;
  CHECK(chooseTablePacking(resident + thesis + output - smallHitList - 1, resident, smallHitList, output, entries,
                           LhtPrecision::Thesis)
            .form == LhtPrecision::Compact);
}

TEST_CASE("app:memory_plan_admits_a_lattice_whose_rasterizing_fits_and_bounds_its_hits") {
  using lattice::app::admitRaster;
  lattice::lht::RasterEstimate e;
  e.distinctPairs = 1'000'000;
  e.hits = 100'000;
  e.fixedBytes = 1000;
  e.rowBytes = 2000;
  const auto table = [](std::uint64_t n) { return 16 * n; };
  const std::uint64_t resident = 5 * MiB, output = 2 * MiB;
  const auto needWith = [&](std::uint64_t n) { return resident + table(n) + std::max(e.bytesFor(n), output); };
  const std::uint64_t need = needWith(e.hits);
  // While rasterizing: the hits (40 B and an allowance each) beside the table being packed.
  CHECK(need == resident + table(e.hits) + e.bytesFor(e.hits));
  CHECK(e.bytesFor(e.hits) == 1000 + 2000 + e.hits * 40 + e.hits * 40 / 16);

  const auto fits = admitRaster(need, resident, output, e, table);
  CHECK(fits.fits);
  CHECK(fits.need == need);
  CHECK(fits.tableBytes == table(e.hits));
  // The running count's limit: the most hits whose need fits.
  CHECK(fits.maxHits >= e.hits);
  CHECK(needWith(fits.maxHits) <= need);
  CHECK(needWith(fits.maxHits + 1) > need);

  const auto refused = admitRaster(need - 1, resident, output, e, table);
  CHECK_FALSE(refused.fits);
  CHECK(refused.maxHits == e.hits - 1);

  // Once the hits are freed the output side comes: it can be what decides.
  const std::uint64_t bigOutput = 64 * MiB;
  const auto afterwards = admitRaster(need, resident, bigOutput, e, table);
  CHECK_FALSE(afterwards.fits);
  CHECK(afterwards.need == resident + table(e.hits) + bigOutput);

  // Never more hits than distinct pairs, whatever the budget.
  CHECK(admitRaster(UINT64_MAX / 2, resident, output, e, table).maxHits == e.distinctPairs);
  // Nothing fits: no hit may be held.
  CHECK(admitRaster(resident, resident, output, e, table).maxHits == 0);
}

TEST_CASE("app:memory_plan_counts_each_table_form_as_it_is_built") {
  using lattice::app::expectedTableBytes;
  using lattice::lht::LhtForm;
  using lattice::lht::LhtPrecision;
  const std::array<int, 3> cells{10, 10, 10};
  // The slots and the occupancy bitmap: 40,000 bits rounded up to 2^16, 8 KiB.
  CHECK(expectedTableBytes(LhtForm::Hashed, LhtPrecision::Thesis, 5000, cells) ==
        lattice::lht::LatticeHashTable::expectedBytes(5000, LhtPrecision::Thesis) + 8192);
  // 602 boundary points: 180,901 unordered pairs, 2,827 words of bitmap, a
  // rank count per 8 words, a 4-byte payload and a 16-byte build pair an entry.
  CHECK(expectedTableBytes(LhtForm::Compressed, LhtPrecision::Thesis, 5000, cells) ==
        2827 * 8 + 354 * 4 + 5000 * (4 + 16));
  // A pair space the compressed form cannot hold is refused before any work.
  CHECK_THROWS_AS(expectedTableBytes(LhtForm::Compressed, LhtPrecision::Thesis, 1, {255, 255, 255}), lattice::Error);
}
