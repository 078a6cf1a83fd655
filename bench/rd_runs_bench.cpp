// rd_runs_bench SCENE --device NAME [--set key=value]... --lambda L --stream FILE -o PNG
//
// Rate-distortion runs at one fixed lambda (quantize/rate_distortion_runs.hpp),
// for measuring what a lambda buys: the render a user gets from `lattice
// render` with the job's rdLambda set, its stream and the emulator's screen
// written. A user never picks lambda by hand: a wire budget searches it
// (app/wire_budget.hpp), so it is a benchmark's setting, not a flag of
// `lattice render`. bench/wire-search.sh part 4 sweeps it for sixel.
#include <fmt/format.h>

#include <string>
#include <vector>

#include "app/render_job.hpp"
#include "bench/bench_main.hpp"
#include "foundation/error.hpp"
#include "foundation/number_text.hpp"

namespace {

using namespace lattice;

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const std::string usage =
      "usage: rd_runs_bench SCENE --device NAME [--set key=value]... --lambda L --stream FILE -o PNG";
  app::RenderJob job;
  job.quiet = true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool value = i + 1 < args.size();
    if (args[i] == "--device" && value) {
      job.output.device = args[++i];
    } else if (args[i] == "--set" && value) {
      job.output.settings.push_back(args[++i]);
    } else if (args[i] == "--lambda" && value) {
      job.rdLambda = parseNumberText("--lambda", args[++i], {0.0, 1e12});
    } else if (args[i] == "--stream" && value) {
      job.output.stream = args[++i];
    } else if (args[i] == "-o" && value) {
      job.output.picture = args[++i];
    } else if (job.scene.empty() && args[i].rfind("-", 0) != 0) {
      job.scene = args[i];
    } else {
      throw Error(ErrorKind::Usage, usage);
    }
  }
  if (job.scene.empty() || job.output.device.empty()) throw Error(ErrorKind::Usage, usage);
  const app::RenderResult result = app::renderScene(job);
  fmt::print("{}x{}, {} bytes\n", result.width, result.height, result.stream ? result.stream->bytes : 0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return lattice::bench::runBenchMain("rd_runs_bench", [&] { return run(argc, argv); });
}
