#include "app/cli/pipeline_args.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <vector>

#include "app/cli/number_flags.hpp"

#include "foundation/error.hpp"

namespace lattice::app {

void addPipelineOptions(CLI::App* cmd, PipelineArgs& args, const std::string& group) {
  const std::size_t before = cmd->get_options().size();
  cmd->add_option("-k,--colors", args.colors,
                  "Palette size K, 1..256 (fewer if the image has fewer colours or the device shows fewer)")
      ->capture_default_str()
      ->check(numberIn({1, 256, true}));
  cmd->add_option("--dither", args.dither, "none | fs (Floyd-Steinberg, serpentine) | bayer (ordered 8x8)")
      ->check(CLI::IsMember(nameList(quantize::kDitherNames)))
      ->capture_default_str();
  cmd->add_option("--split", args.split, "median (Heckbert 1982) | variance (minimise squared error)")
      ->check(CLI::IsMember(nameList(quantize::kSplitRuleNames)))
      ->capture_default_str();
  cmd->add_option("--refine", args.refine, "k-means refinement iterations after the cut, 0..100")
      ->capture_default_str()
      ->check(numberIn({0, 100, true}));
  cmd->add_option("--mode", args.mode,
                  "passes (render twice: least memory) | frame (keep the 18-bit frame: fastest) | sample "
                  "(histogram of a subsampled pre-pass)")
      ->check(CLI::IsMember(nameList(quantize::kPipelineModeNames)))
      ->capture_default_str();
  cmd->add_option("--sample", args.sample, "sample mode: histogram from every Nth row and column (default 4)")
      ->check(numberIn({1, 16384, true}));
  cmd->add_option("--histogram", args.histogram,
                  "full (a counter per 18-bit colour, 1 MiB) | small (only the colours present, at most 64 KiB and "
                  "6144 colours: the firmware's form, docs/firmware.md); the same palette either way")
      ->check(CLI::IsMember(nameList(quantize::kHistogramFormNames)))
      ->capture_default_str();
  const std::vector<CLI::Option*> options = cmd->get_options();
  for (std::size_t i = before; i < options.size(); ++i) options[i]->group(group);
  cmd->add_flag("-q,--quiet", args.quiet, "no progress bars")->group("Report");
}

quantize::PipelineOptions toPipelineOptions(const PipelineArgs& args, const CLI::App& cmd) {
  quantize::PipelineOptions options;
  options.maxColors = args.colors;
  // Values checked by CLI::IsMember against the same tables.
  options.quantize.dither = *valueNamed(quantize::kDitherNames, args.dither);
  options.quantize.split = *valueNamed(quantize::kSplitRuleNames, args.split);
  options.quantize.refineIterations = args.refine;
  options.quantize.histogram = *valueNamed(quantize::kHistogramFormNames, args.histogram);
  const bool sampleGiven = cmd.count("--sample") > 0;
  const bool modeGiven = cmd.count("--mode") > 0;
  options.mode = *valueNamed(quantize::kPipelineModeNames, args.mode);
  if (sampleGiven && !modeGiven) options.mode = quantize::PipelineMode::Sample;
  if (sampleGiven && options.mode != quantize::PipelineMode::Sample)
    throw Error(ErrorKind::Usage, fmt::format("--sample only applies to --mode sample (got --mode {})", args.mode));
  if (options.mode == quantize::PipelineMode::Sample) {
    options.sampleStep = sampleGiven ? args.sample : 4;
    if (options.sampleStep < 1)
      throw Error(ErrorKind::Usage, fmt::format("--sample {} is out of range: give a step of 1 or more", args.sample));
  }
  options.progress = !args.quiet;
  return options;
}

}  // namespace lattice::app
