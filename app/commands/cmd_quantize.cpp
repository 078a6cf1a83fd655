// `lattice quantize`: any PNG through the same 18-bit median-cut pipeline a
// rendered picture takes, written as a palette PNG.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>

#include "app/commands/commands.hpp"
#include "app/cli/pipeline_args.hpp"
#include "io/png.hpp"
#include "foundation/indexed_image.hpp"
#include "foundation/rgb_image_source.hpp"
#include "quantize/run_pipeline.hpp"
#include "foundation/error.hpp"

namespace {

struct QuantizeArgs {
  std::string input;
  std::string output;
  lattice::app::PipelineArgs pipeline;
  bool verbose = false;
};

void runQuantize(const QuantizeArgs& args) {
  lattice::quantize::PipelineOptions options = lattice::app::toPipelineOptions(args.pipeline);
  std::filesystem::path output(args.output);
  if (std::filesystem::is_directory(output))
    throw lattice::Error(lattice::ErrorKind::Output,
                         fmt::format("{}: is a directory; give -o a file name such as {}/out.png", args.output,
                                     args.output));
  lattice::RgbImage image = lattice::io::readPng(args.input);  // Error(Input) naming the file
  lattice::RgbImageSource source(image);
  lattice::IndexedImageSink sink(options.maxColors);
  lattice::quantize::PipelineReport report = lattice::quantize::runPipeline(source, sink, options);
  lattice::io::writePng(output, sink.image());  // atomic; Error(Output) naming the file
  if (args.verbose)
    fmt::print("{}: {}x{}, {} distinct 18-bit colours -> {} palette entries ({} mode, {} rows rendered, {} KiB of "
               "pipeline buffers)\n",
               args.output, image.width, image.height, report.distinctColors, report.paletteSize,
               lattice::quantize::pipelineModeName(options.mode), report.rowsRendered, (report.totalBytes() + 1023) / 1024);
}

}  // namespace

namespace lattice::app {

void addQuantize(CLI::App& root) {
  auto args = std::make_shared<QuantizeArgs>();
  CLI::App* cmd = root.add_subcommand(
      "quantize",
      "Reduce any PNG to at most K colours with Heckbert's median cut (the thesis's 18-bit path: each channel is\n"
      "first rounded to 6 bits) and write a palette PNG. See docs/quantize.md for the options' measured effect.");
  cmd->add_option("input", args->input, "PNG to quantize")->required();
  cmd->add_option("-o,--output", args->output, "palette PNG to write (atomically)")->required();
  lattice::app::addPipelineOptions(cmd, args->pipeline);
  cmd->add_flag("-v,--verbose", args->verbose, "print the palette size and buffer memory");
  cmd->callback([args] { runQuantize(*args); });
}

}  // namespace lattice::app
