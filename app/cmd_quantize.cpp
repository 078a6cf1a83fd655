// `lattice quantize`: any PNG through the same 18-bit median-cut pipeline a
// rendered picture takes, written as a palette PNG.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "app/command_registry.hpp"
#include "io/png.hpp"
#include "pipeline/indexed_image.hpp"
#include "pipeline/rgb_image_source.hpp"
#include "pipeline/run_pipeline.hpp"
#include "util/error.hpp"

namespace {

struct QuantizeArgs {
  std::string input;
  std::string output;
  int colors = 256;
  std::string dither = "none";
  std::string split = "median";
  int refine = 0;
  std::string mode = "passes";
  int sample = 0;
  bool quiet = false;
  bool verbose = false;
};

lattice::PipelineOptions toOptions(const QuantizeArgs& args, const CLI::App& cmd) {
  using lattice::Error;
  using lattice::ErrorKind;
  lattice::PipelineOptions options;
  options.maxColors = args.colors;
  if (args.colors < 1 || args.colors > 256)
    throw Error(ErrorKind::Usage, fmt::format("--colors {} is out of range: give 1 to 256", args.colors));
  static const std::map<std::string, lattice::Dither> dithers{
      {"none", lattice::Dither::None}, {"fs", lattice::Dither::FloydSteinberg}, {"bayer", lattice::Dither::Bayer}};
  static const std::map<std::string, lattice::SplitRule> splits{{"median", lattice::SplitRule::Median},
                                                                {"variance", lattice::SplitRule::Variance}};
  static const std::map<std::string, lattice::PipelineMode> modes{{"passes", lattice::PipelineMode::TwoPass},
                                                                  {"frame", lattice::PipelineMode::Frame},
                                                                  {"sample", lattice::PipelineMode::Sample}};
  options.quantize.dither = dithers.at(args.dither);  // values checked by CLI::IsMember
  options.quantize.split = splits.at(args.split);
  options.quantize.refineIterations = args.refine;
  bool sampleGiven = cmd.count("--sample") > 0;
  bool modeGiven = cmd.count("--mode") > 0;
  options.mode = modes.at(args.mode);
  if (sampleGiven && !modeGiven) options.mode = lattice::PipelineMode::Sample;
  if (sampleGiven && options.mode != lattice::PipelineMode::Sample)
    throw Error(ErrorKind::Usage, fmt::format("--sample only applies to --mode sample (got --mode {})", args.mode));
  if (options.mode == lattice::PipelineMode::Sample) {
    options.sampleStep = sampleGiven ? args.sample : 4;
    if (options.sampleStep < 1)
      throw Error(ErrorKind::Usage, fmt::format("--sample {} is out of range: give a step of 1 or more", args.sample));
  }
  options.progress = !args.quiet;
  return options;
}

void runQuantize(const QuantizeArgs& args, const CLI::App& cmd) {
  lattice::PipelineOptions options = toOptions(args, cmd);
  std::filesystem::path output(args.output);
  if (std::filesystem::is_directory(output))
    throw lattice::Error(lattice::ErrorKind::Output,
                         fmt::format("{}: is a directory; give -o a file name such as {}/out.png", args.output,
                                     args.output));
  lattice::RgbImage image = lattice::readPng(args.input);  // Error(Input) naming the file
  lattice::RgbImageSource source(image);
  lattice::IndexedImageSink sink(args.colors);
  lattice::PipelineReport report = lattice::runPipeline(source, sink, options);
  lattice::writePng(output, sink.image());  // atomic; Error(Output) naming the file
  if (args.verbose)
    fmt::print("{}: {}x{}, {} distinct 18-bit colours -> {} palette entries ({} mode, {} rows rendered, {} KiB of "
               "pipeline buffers)\n",
               args.output, image.width, image.height, report.distinctColors, report.paletteSize,
               lattice::pipelineModeName(options.mode), report.rowsRendered, (report.totalBytes() + 1023) / 1024);
}

void addQuantize(CLI::App& root) {
  auto args = std::make_shared<QuantizeArgs>();
  CLI::App* cmd = root.add_subcommand(
      "quantize",
      "Reduce any PNG to at most K colours with Heckbert's median cut (the thesis's 18-bit path: each channel is\n"
      "first rounded to 6 bits) and write a palette PNG. See docs/quantize.md for the options' measured effect.");
  cmd->add_option("input", args->input, "PNG to quantize")->required();
  cmd->add_option("-o,--output", args->output, "palette PNG to write (atomically)")->required();
  cmd->add_option("-k,--colors", args->colors, "palette size K, 1..256 (fewer if the image has fewer colours)")
      ->capture_default_str();
  cmd->add_option("--dither", args->dither, "none | fs (Floyd-Steinberg, serpentine) | bayer (ordered 8x8)")
      ->check(CLI::IsMember({"none", "fs", "bayer"}))
      ->capture_default_str();
  cmd->add_option("--split", args->split, "median (Heckbert 1982) | variance (minimise squared error)")
      ->check(CLI::IsMember({"median", "variance"}))
      ->capture_default_str();
  cmd->add_option("--refine", args->refine, "k-means refinement iterations after the cut, 0..100")
      ->capture_default_str();
  cmd->add_option("--mode", args->mode,
                  "passes (read twice, least memory) | frame (keep the 18-bit frame) | sample (histogram of a "
                  "subsample)")
      ->check(CLI::IsMember({"passes", "frame", "sample"}))
      ->capture_default_str();
  cmd->add_option("--sample", args->sample, "sample mode: histogram from every Nth row and column (default 4)");
  cmd->add_flag("-q,--quiet", args->quiet, "no progress bars");
  cmd->add_flag("-v,--verbose", args->verbose, "print the palette size and buffer memory");
  cmd->callback([args, cmd] { runQuantize(*args, *cmd); });
}

}  // namespace

LATTICE_COMMAND(addQuantize);
