#pragma once
// The quantizer flags shared by `lattice quantize` and `lattice render`
// (--colors, --dither, --split, --refine, --mode, --sample, --histogram, --quiet), turned
// into PipelineOptions in one place so both commands mean the same thing.

#include <string>

#include "app/cli/cli_forward.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {

struct PipelineArgs {
  int colors = 256;  // upper bound; a device may allow fewer
  std::string dither = "none";
  std::string split = "median";
  int refine = 0;
  std::string mode = "passes";
  int sample = 0;
  std::string histogram = "full";
  bool quiet = false;
};

// `group`: the help group the quantizer flags are listed under (--quiet is
// listed under "Report" either way).
void addPipelineOptions(CLI::App* cmd, PipelineArgs& args, const std::string& group = "Quantizer");
// Throws lattice::Error(Usage) for combinations CLI11 cannot check alone.
quantize::PipelineOptions toPipelineOptions(const PipelineArgs& args, const CLI::App& cmd);

}  // namespace lattice::app
