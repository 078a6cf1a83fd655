#include "app/cli/pipeline_args.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice::app {

void addPipelineOptions(CLI::App* cmd, PipelineArgs& args, const std::string& group,
                        std::span<const std::string_view> keys) {
  addSettingFlags(cmd, quantize::pipelineSettings(), args.initial, args.given, keys, group, {{"colors", "k"}});
  cmd->add_flag("-q,--quiet", args.quiet, "no progress bars")->group("Report");
}

quantize::PipelineOptions toPipelineOptions(const PipelineArgs& args) {
  quantize::PipelineOptions options = args.initial;
  applySettingFlags(quantize::pipelineSettings(), options, args.given);
  // A sample step asks for sample mode unless --mode says otherwise, and
  // then it contradicts it.
  const bool sampleGiven = args.given.contains("sample"), modeGiven = args.given.contains("mode");
  if (sampleGiven && !modeGiven) options.mode = quantize::PipelineMode::Sample;
  if (sampleGiven && options.mode != quantize::PipelineMode::Sample)
    throw Error(ErrorKind::Usage, fmt::format("--sample only applies to --mode sample (got --mode {})",
                                              args.given.find("mode")->second));
  options.progress = !args.quiet;
  return options;
}

}  // namespace lattice::app
