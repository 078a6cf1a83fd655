#include "app/cli/wire_args.hpp"

#include <CLI/CLI.hpp>

#include "app/cli/number_flags.hpp"

#include "foundation/system/resident_memory.hpp"
#include "foundation/error.hpp"

namespace lattice::app {

void addWireOptions(CLI::App* cmd, WireArgs& args) {
  const char* group = "Wire budget";
  cmd->add_option("--rd-lambda", args.lambda,
                  "Devices: rate-distortion runs, squared 8-bit RGB error a byte is worth (0: lossless, the "
                  "stream as always; 1000s give fewer, longer runs; docs/wire.md)")
      ->check(numberIn({0.0, 1e12}))
      ->group(group);
  cmd->add_option("--wire-seconds", args.seconds,
                  "Devices: send the most accurate picture whose stream takes at most S seconds at --baud (default: "
                  "the profile's); searches palette size, dithering and --rd-lambda with the real encoder; exits 8 "
                  "with the smallest stream if nothing fits")
      ->check(numberIn({0.001, 1e9}))
      ->group(group);
  cmd->add_option("--wire-bytes", args.bytes, "Devices: as --wire-seconds, a budget of N bytes (57600, 56K)")
      ->group(group);
  cmd->add_option("--wire-quality", args.quality,
                  "With a wire budget and no --width/--height: send the largest picture (up to the device's "
                  "drawable area, at the scene's aspect) whose stream fits with at least this PSNR in dB against "
                  "the truecolour render at that size (docs/wire.md)")
      ->check(numberIn({1.0, 99.0}))
      ->capture_default_str()
      ->group(group);
  cmd->add_flag("--wire-shrink", args.shrink,
                "With a wire budget: when nothing fits, send a smaller picture (each side x0.8 until it fits)")
      ->group(group);
}

void applyWireArgs(const WireArgs& args, const CLI::App& cmd, int baud, RenderJob& job) {
  job.rdLambda = args.lambda;
  const bool seconds = cmd.count("--wire-seconds") > 0, bytes = cmd.count("--wire-bytes") > 0;
  if (args.shrink && !seconds && !bytes)
    throw Error(ErrorKind::Usage, "--wire-shrink applies to a wire budget: add --wire-seconds S or --wire-bytes N");
  const bool quality = cmd.count("--wire-quality") > 0;
  if (quality && !seconds && !bytes)
    throw Error(ErrorKind::Usage, "--wire-quality is the floor of a wire budget's size search: add --wire-seconds S "
                                  "or --wire-bytes N");
  if (quality && (cmd.count("--width") > 0 || cmd.count("--height") > 0))
    throw Error(ErrorKind::Usage, "--wire-quality chooses the picture's size, and --width/--height fix it: drop one "
                                  "or the other");
  if (!seconds && !bytes) return;
  if (seconds && bytes)
    throw Error(ErrorKind::Usage, "--wire-seconds and --wire-bytes are two budgets for one stream; give one (at 8N1 "
                                  "a second is baud / 10 bytes: 60 s at 9600 baud is --wire-bytes 57600)");
  WireBudget budget;
  if (seconds) budget.seconds = args.seconds;
  if (bytes) budget.bytes = parseByteCount(args.bytes, "--wire-bytes");
  if (cmd.count("--baud") > 0) budget.baud = baud;
  budget.shrink = args.shrink;
  budget.quality = args.quality;
  job.wire = budget;
}

}  // namespace lattice::app
