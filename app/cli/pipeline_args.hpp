#pragma once
// The quantizer flags of `lattice quantize`, `render` and `bake`, read from
// the quantizer's settings schema (quantize/pipeline_settings.hpp) and turned
// into PipelineOptions in one place, so every command means the same thing.

#include <span>
#include <string>
#include <string_view>

#include "app/cli/cli_forward.hpp"
#include "app/cli/setting_flags.hpp"
#include "quantize/pipeline_settings.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {

struct PipelineArgs {
  // The options before any flag; a command may change a default first
  // (bake's small histogram).
  quantize::PipelineOptions initial = quantize::pipelineSettings().initial();
  SettingFlagValues given;
  bool quiet = false;
};

// Every quantizer setting; `render` leaves out the palette's fine tuning.
inline constexpr std::string_view kAllPipelineKeys[] = {"colors", "dither", "split", "refine",
                                                        "mode",   "sample", "histogram"};
inline constexpr std::string_view kRenderPipelineKeys[] = {"colors", "dither", "mode", "sample", "histogram"};

// `group`: the help group the quantizer flags are listed under (--quiet is
// listed under "Report" either way).
void addPipelineOptions(CLI::App* cmd, PipelineArgs& args, const std::string& group = "Quantizer",
                        std::span<const std::string_view> keys = kAllPipelineKeys);
// Throws lattice::Error(Usage) for combinations CLI11 cannot check alone.
quantize::PipelineOptions toPipelineOptions(const PipelineArgs& args);

}  // namespace lattice::app
